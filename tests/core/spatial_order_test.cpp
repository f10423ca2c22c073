#include "core/spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>

#include "core/structured_mesh.h"
#include "tests/support/random_vec3.h"

namespace tfd::core {
namespace {

// Only a Hilbert curve passes both: every cell of the grid gets its own index 0..8^bits − 1,
// and cells with consecutive indices share a face (Z-order and scan orders jump).
TEST(HilbertIndex, VisitsEveryCellOnceAndStepsToAFaceNeighbour) {
  for (int bits = 1; bits <= 4; ++bits) {
    const std::uint32_t n = 1u << bits;
    std::vector<std::array<std::uint32_t, 3>> byIndex(std::size_t(n) * n * n, {n, n, n});
    for (std::uint32_t x = 0; x < n; ++x)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t z = 0; z < n; ++z) {
          const std::uint64_t h = hilbertIndex({x, y, z}, bits);
          ASSERT_LT(h, byIndex.size());
          ASSERT_EQ(byIndex[h][0], n) << "index " << h << " given twice";
          byIndex[h] = {x, y, z};
        }
    EXPECT_EQ(byIndex.front(), (std::array<std::uint32_t, 3>{0, 0, 0}));
    for (std::size_t h = 1; h < byIndex.size(); ++h) {
      int steps = 0;
      for (int a = 0; a < 3; ++a) steps += std::abs(int(byIndex[h][a]) - int(byIndex[h - 1][a]));
      ASSERT_EQ(steps, 1) << "bits " << bits << ", index " << h;
    }
  }
  EXPECT_THROW(hilbertIndex({0, 0, 0}, 0), Error);
  EXPECT_THROW(hilbertIndex({0, 0, 0}, 22), Error);
}

TEST(HilbertOrder, IsAPermutationThatKeepsNearbyPointsNearby) {
  std::mt19937 rng(7);
  std::vector<Vec3> points(20000);
  std::uniform_real_distribution<double> u(-1, 1);
  for (Vec3& p : points) p = test::drawVec3(u, rng);
  points.push_back(Vec3(std::nan(""), 0, 0));  // not finite: cell 0, no crash
  const std::vector<int> order = hilbertOrder(points);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], int(i));
  // Consecutive points of the order are close: mean step ~ the spacing (20000^(-1/3) ≈ 0.04
  // per unit), against ~1 for the input's random order.
  double step = 0;
  for (std::size_t k = 1; k + 1 < order.size(); ++k)
    if (points[order[k]].allFinite() && points[order[k - 1]].allFinite())
      step += (points[order[k]] - points[order[k - 1]]).norm();
  EXPECT_LT(step / double(order.size()), 0.15);
  EXPECT_TRUE(hilbertOrder(std::vector<Vec3>{}).empty());
}

TEST(RenumberSpatially, KeepsTheFixedVerticesTheTetsAndTheirOrientation) {
  const auto mesh = makeBoxMesh(12, 10, 8, Vec3(-1, -1, -1), Vec3(1, 2, 1));
  std::vector<Vec3> positions = mesh->positions();
  std::vector<std::array<int, 4>> tets = mesh->tets();
  std::reverse(tets.begin(), tets.end());
  const std::size_t fixed = 100;
  auto key = [&](const std::vector<Vec3>& p, const std::array<int, 4>& t) {
    std::array<std::array<double, 3>, 4> k;
    for (int i = 0; i < 4; ++i) k[i] = {p[t[i]].x(), p[t[i]].y(), p[t[i]].z()};
    return k;  // the corners' positions in the tet's own order: id-free, orientation-aware
  };
  std::set<std::array<std::array<double, 3>, 4>> before, after;
  for (const auto& t : tets) before.insert(key(positions, t));
  const std::vector<Vec3> old = positions;
  renumberSpatially(positions, tets, fixed);
  for (std::size_t v = 0; v < fixed; ++v) EXPECT_EQ(positions[v], old[v]);
  for (const auto& t : tets) after.insert(key(positions, t));
  EXPECT_EQ(before, after);
  std::vector<std::array<int, 4>> bad = {{0, 1, 2, int(positions.size())}};
  EXPECT_THROW(renumberSpatially(positions, bad, 0), Error);
}

}  // namespace
}  // namespace tfd::core
