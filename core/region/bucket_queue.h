#pragma once
// A min-priority queue of (key, id) pairs, keys ≥ 0, that pops in exactly the order of
// std::priority_queue<std::pair<double, int>, …, std::greater<>> (ascending key, then id): the
// region growing of ball_region.h keeps its order, and so its regions, bit for bit.
//
// Keys are bucketed by width: pairs in buckets up to the current one live in a binary heap,
// later ones in unsorted per-bucket lists that move into the heap when it runs dry. Every pair
// in the heap is smaller than every pair in a later bucket, so the heap's top is the global
// minimum. A front of a few thousand tets then sifts through a small, cache-resident heap
// instead of one holding the whole region (log of the bucket, not of the region, and no cache
// misses deep in the tree). A key below the current bucket (the fronts are not monotone) simply
// joins the heap.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace tfd::core {

class BucketQueue {
 public:
  using Entry = std::pair<double, int>;
  /// `width` > 0: the key range of one bucket (a fraction of the mean edge length suits a
  /// distance front).
  explicit BucketQueue(double width) : inverseWidth_(1.0 / width) {}

  bool empty() const { return heap_.empty() && pending_ == 0; }
  void emplace(double key, int id) {
    const std::size_t b = bucketOf(key);
    if (b <= current_) {
      heap_.emplace_back(key, id);
      std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
      return;
    }
    if (b >= buckets_.size()) buckets_.resize(b + 1);
    buckets_[b].emplace_back(key, id);
    ++pending_;
  }
  /// The smallest pair; the queue must not be empty.
  const Entry& top() {
    refill();
    return heap_.front();
  }
  void pop() {
    refill();
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    heap_.pop_back();
  }

 private:
  static constexpr std::size_t kMaxBuckets = std::size_t(1) << 16;  // beyond: one last bucket
  std::size_t bucketOf(double key) const {
    const double b = key * inverseWidth_;
    return b < double(kMaxBuckets) ? std::size_t(b) : kMaxBuckets;  // monotone in key
  }
  void refill() {
    while (heap_.empty() && pending_ > 0) {
      std::vector<Entry>& next = buckets_[++current_];
      if (next.empty()) continue;
      pending_ -= next.size();
      heap_.assign(next.begin(), next.end());
      std::make_heap(heap_.begin(), heap_.end(), std::greater<>());
      std::vector<Entry>().swap(next);
    }
  }

  double inverseWidth_;
  std::vector<Entry> heap_;
  std::vector<std::vector<Entry>> buckets_;
  std::size_t current_ = 0, pending_ = 0;
};

}  // namespace tfd::core
