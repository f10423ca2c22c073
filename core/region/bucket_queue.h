#pragma once
// Priority queues that pop in exactly the order of a std::priority_queue, for the sequential
// greedy loops of the edits: region growing (ball_region.h) and the spanning tree that orients
// an eigenvector (core/edit/vectorise_eigenvector.h) keep their order, and so their results,
// bit for bit.
//
// The caller gives each entry a bucket number that never decreases along the pop order (an
// entry popped before another has a bucket ≤ the other's). Entries in buckets up to the current
// one live in a binary heap, later ones in unsorted per-bucket lists that move into the heap
// when it runs dry. Every entry in the heap pops before every entry in a later bucket, so the
// heap's top is the global first. A front of a few thousand entries then sifts through a small,
// cache-resident heap instead of one holding everything pushed (log of the bucket, not of the
// whole queue, and no cache misses deep in the tree). An entry below the current bucket (the
// keys are not monotone) simply joins the heap.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

namespace tfd::core {

/// Pops in the order of std::priority_queue<Entry, std::vector<Entry>, HeapLess>: `top()` is
/// an entry that no other is HeapLess-greater than.
template <class Entry, class HeapLess>
class OrderedBucketQueue {
 public:
  /// Bucket numbers at and beyond this share the last bucket (keeps the bucket list small).
  static constexpr std::size_t kMaxBuckets = std::size_t(1) << 16;

  bool empty() const { return heap_.empty() && pending_ == 0; }
  /// `bucket` must not decrease along the pop order (see above).
  void emplace(std::size_t bucket, const Entry& entry) {
    const std::size_t b = std::min(bucket, kMaxBuckets);
    if (b <= current_) {
      heap_.push_back(entry);
      std::push_heap(heap_.begin(), heap_.end(), HeapLess());
      return;
    }
    if (b >= buckets_.size()) buckets_.resize(b + 1);
    buckets_[b].push_back(entry);
    ++pending_;
  }
  /// The first entry; the queue must not be empty.
  const Entry& top() {
    refill();
    return heap_.front();
  }
  void pop() {
    refill();
    std::pop_heap(heap_.begin(), heap_.end(), HeapLess());
    heap_.pop_back();
  }
  /// The entry that pops after top() when it is already in the heap (else null): a hint for
  /// loading ahead, valid until the next change of the queue. Call after top().
  const Entry* second() const {
    if (heap_.size() < 2) return nullptr;
    if (heap_.size() == 2 || HeapLess()(heap_[2], heap_[1])) return &heap_[1];
    return &heap_[2];
  }

 private:
  void refill() {
    while (heap_.empty() && pending_ > 0) {
      std::vector<Entry>& next = buckets_[++current_];
      if (next.empty()) continue;
      pending_ -= next.size();
      heap_.assign(next.begin(), next.end());
      std::make_heap(heap_.begin(), heap_.end(), HeapLess());
      std::vector<Entry>().swap(next);
    }
  }

  std::vector<Entry> heap_;
  std::vector<std::vector<Entry>> buckets_;
  std::size_t current_ = 0, pending_ = 0;
};

/// A min-priority queue of (key, id) pairs, keys ≥ 0, popping in exactly the order of
/// std::priority_queue<std::pair<double, int>, …, std::greater<>> (ascending key, then id),
/// keys bucketed by `width` (a fraction of the mean edge length suits a distance front).
class BucketQueue {
 public:
  using Entry = std::pair<double, int>;
  explicit BucketQueue(double width) : inverseWidth_(1.0 / width) {}

  bool empty() const { return queue_.empty(); }
  void emplace(double key, int id) { queue_.emplace(bucketOf(key), Entry(key, id)); }
  const Entry& top() { return queue_.top(); }
  void pop() { queue_.pop(); }
  const Entry* second() const { return queue_.second(); }

 private:
  using Queue = OrderedBucketQueue<Entry, std::greater<>>;
  std::size_t bucketOf(double key) const {
    const double b = key * inverseWidth_;
    return b < double(Queue::kMaxBuckets) ? std::size_t(b) : Queue::kMaxBuckets;  // monotone
  }

  double inverseWidth_;
  Queue queue_;
};

/// A bucket number for keys ≥ 0 spread over many orders of magnitude, non-decreasing in the
/// key: 0 up to 2^-40, then 64 buckets per power of two (the bit pattern of a positive double
/// is monotone in its value), up to about 3300 buckets for keys near 1.
inline std::size_t logBucket(double key) {
  constexpr double kSmallest = 0x1p-40;
  if (!(key > kSmallest)) return 0;  // also a negative key (rounding) or NaN
  std::uint64_t bits = 0, base = 0;
  std::memcpy(&bits, &key, sizeof bits);
  std::memcpy(&base, &kSmallest, sizeof base);
  return std::size_t((bits >> 46) - (base >> 46)) + 1;
}

}  // namespace tfd::core
