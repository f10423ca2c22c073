// The bucketed queues of core/region/bucket_queue.h pop in exactly the order of
// std::priority_queue: with std::greater on (key, id) (the order the regions were grown in
// before it), and the max-queue of (weight, −vertex, parent) of the spanning tree that orients
// an eigenvector, bucketed by logBucket(1 − weight); for interleaved pushes and pops with keys
// below the current bucket, ties and repeats.
#include "core/region/bucket_queue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <random>
#include <tuple>

namespace tfd::core {
namespace {

/// Pops both queues to the end, entry by entry equal.
template <class Queue, class Reference>
void expectDrainsInOrder(Queue& queue, Reference& reference) {
  while (!reference.empty()) {
    ASSERT_EQ(queue.top(), reference.top());
    queue.pop(), reference.pop();
  }
  EXPECT_TRUE(queue.empty());
}

TEST(BucketQueue, PopsInThePriorityQueueOrder) {
  for (const double width : {1e-3, 0.05, 0.3, 10.0}) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>>
        reference;
    BucketQueue queue(width);
    double front = 0;  // keys mostly grow like a front's, some fall behind it
    int pops = 0, seconds = 0;
    for (int step = 0; step < 20000; ++step) {
      if (reference.empty() || u(rng) < 0.55) {
        const double ahead = 0.2 * u(rng);  // one draw per statement: the same keys everywhere
        const double behind = u(rng) < 0.1 ? 0.3 * u(rng) : 0.0;
        double key = front + ahead - behind;
        key = std::max(key, 0.0);
        if (u(rng) < 0.05) key = std::floor(key * 10) / 10;  // exact ties
        const int id = int(rng() % 500);
        reference.emplace(key, id);
        queue.emplace(key, id);
      } else {
        ASSERT_FALSE(queue.empty());
        ASSERT_EQ(queue.top(), reference.top()) << "width " << width << " pop " << pops;
        front = std::max(front, reference.top().first);
        std::optional<std::pair<double, int>> second;  // when known, the one after top()
        if (const auto* s = queue.second()) second = *s;
        queue.pop();
        reference.pop();
        if (second) {
          ASSERT_FALSE(reference.empty());
          ASSERT_EQ(*second, reference.top()) << "width " << width << " pop " << pops;
          ++seconds;
        }
        ++pops;
      }
      ASSERT_EQ(queue.empty(), reference.empty());
    }
    expectDrainsInOrder(queue, reference);
    EXPECT_GT(pops, 5000);
    EXPECT_GT(seconds, width < 1 ? 1000 : 4000);
  }
  // Keys far beyond the last bucket share it and still come out in order.
  BucketQueue far(1e-6);
  far.emplace(1e9, 2), far.emplace(5e8, 1), far.emplace(1e9, 1), far.emplace(0, 7);
  const std::pair<double, int> expected[] = {{0, 7}, {5e8, 1}, {1e9, 1}, {1e9, 2}};
  for (const auto& e : expected) {
    ASSERT_EQ(far.top(), e);
    far.pop();
  }
  EXPECT_TRUE(far.empty());
}

TEST(BucketQueue, LogBucketsKeepTheMaxQueueOrderOfTheSpanningTree) {
  // Weights |cos| mostly close to 1 (a smooth field), some far from it, exact ties, and the
  // rounding cases 1 − w < 0 and w = 0.
  using Entry = std::tuple<double, int, int>;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::priority_queue<Entry> reference;
  OrderedBucketQueue<Entry, std::less<>> queue;
  int pops = 0;
  for (int step = 0; step < 30000; ++step) {
    if (reference.empty() || u(rng) < 0.55) {
      double w = 1 - std::pow(10.0, -12 * u(rng));
      if (u(rng) < 0.1) w = u(rng);
      if (u(rng) < 0.05) w = std::floor(w * 1000) / 1000;
      if (u(rng) < 0.01) w = u(rng) < 0.5 ? 1 + 1e-16 * 2 : 0.0;
      const int a = -int(rng() % 300), b = int(rng() % 300);  // one draw per declarator: in order
      const Entry e(w, a, b);
      reference.push(e);
      queue.emplace(logBucket(1 - w), e);
    } else {
      ASSERT_EQ(queue.top(), reference.top()) << "pop " << pops;
      queue.pop(), reference.pop();
      ++pops;
    }
    ASSERT_EQ(queue.empty(), reference.empty());
  }
  expectDrainsInOrder(queue, reference);
  EXPECT_GT(pops, 10000);
  // Non-decreasing in the key, over many orders of magnitude.
  std::size_t last = 0;
  for (double k = 1e-20; k < 4; k *= 1.01) {
    EXPECT_GE(logBucket(k), last) << k;
    last = logBucket(k);
  }
  EXPECT_EQ(logBucket(-1e-17), 0u);
  EXPECT_GT(logBucket(1.0), logBucket(0.5));
}

}  // namespace
}  // namespace tfd::core
