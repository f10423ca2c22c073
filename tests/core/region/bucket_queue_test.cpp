// The bucketed queue of region growing (core/region/bucket_queue.h) pops in exactly the order
// of std::priority_queue with std::greater (the order the regions were grown in before it), for
// interleaved pushes and pops with keys below the current bucket, ties and repeats.
#include "core/region/bucket_queue.h"

#include <gtest/gtest.h>

#include <queue>
#include <random>

namespace tfd::core {
namespace {

TEST(BucketQueue, PopsInThePriorityQueueOrder) {
  for (const double width : {1e-3, 0.05, 0.3, 10.0}) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>>
        reference;
    BucketQueue queue(width);
    double front = 0;  // keys mostly grow like a front's, some fall behind it
    int pops = 0;
    for (int step = 0; step < 20000; ++step) {
      if (reference.empty() || u(rng) < 0.55) {
        double key = front + 0.2 * u(rng) - (u(rng) < 0.1 ? 0.3 * u(rng) : 0.0);
        key = std::max(key, 0.0);
        if (u(rng) < 0.05) key = std::floor(key * 10) / 10;  // exact ties
        const int id = int(rng() % 500);
        reference.emplace(key, id);
        queue.emplace(key, id);
      } else {
        ASSERT_FALSE(queue.empty());
        ASSERT_EQ(queue.top(), reference.top()) << "width " << width << " pop " << pops;
        front = std::max(front, reference.top().first);
        queue.pop();
        reference.pop();
        ++pops;
      }
      ASSERT_EQ(queue.empty(), reference.empty());
    }
    while (!reference.empty()) {
      ASSERT_EQ(queue.top(), reference.top());
      queue.pop(), reference.pop();
    }
    EXPECT_TRUE(queue.empty());
    EXPECT_GT(pops, 5000);
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

}  // namespace
}  // namespace tfd::core
