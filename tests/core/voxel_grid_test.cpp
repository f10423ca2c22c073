// core::insideMask: the parity of boundary crossings per row of voxels, checked against the
// point locator (an independent answer) and on rows that run exactly through boundary edges and
// vertices, where a crossing counted twice or not at all would flip a whole row.
#include "core/voxel_grid.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/point_locator.h"
#include "core/structured_mesh.h"
#include "tests/support/carved_ball.h"

namespace tfd::core {
namespace {

TEST(InsideMask, MatchesThePointLocatorOnACarvedBall) {
  const auto mesh = test::carvedBall(14, Vec3(0.1, -0.2, 0.05), 1.0);
  VoxelGrid grid;
  grid.voxelSize = 0.043;
  grid.origin = Vec3(0.013, -0.007, 0.021);  // centres off the mesh's planes
  grid.min = {-28, -32, -27};
  grid.max = {30, 24, 28};
  const std::vector<std::uint8_t> mask = insideMask(*mesh, grid);
  ASSERT_EQ(mask.size(), grid.count());
  std::size_t inside = 0, disagree = 0;
  for (int k = grid.min[2]; k <= grid.max[2]; ++k)
    for (int j = grid.min[1]; j <= grid.max[1]; ++j)
      for (int i = grid.min[0]; i <= grid.max[0]; ++i) {
        const bool located = mesh->locator().locate(grid.centre(i, j, k)).has_value();
        inside += located;
        disagree += located != (mask[grid.offset(i, j, k)] != 0);
      }
  EXPECT_GT(inside, grid.count() / 4);
  EXPECT_EQ(disagree, 0u);
}

TEST(InsideMask, RowsThroughBoundaryEdgesAndVerticesCountEachCrossingOnce) {
  // Voxel centres at multiples of 1/8 on a 4³ Kuhn box of [0, 1]³: every row with j, k in
  // 1 … 7 runs through the boundary faces' edges or vertices at x = 0 and x = 1 (the grid
  // lines at quarters, the cube diagonals where j = k).
  const auto mesh = makeBoxMesh(4, 4, 4, Vec3::Zero(), Vec3::Ones());
  VoxelGrid grid;
  grid.voxelSize = 0.125;
  grid.min = {-2, -2, -2};
  grid.max = {10, 10, 10};
  for (int threads : {1, 2}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    const std::vector<std::uint8_t> mask = insideMask(*mesh, grid);
    for (int k = grid.min[2]; k <= grid.max[2]; ++k)
      for (int j = grid.min[1]; j <= grid.max[1]; ++j)
        for (int i = grid.min[0]; i <= grid.max[0]; ++i) {
          const auto strictly = [](int n) { return n >= 1 && n <= 7; };
          const auto outside = [](int n) { return n < 0 || n > 8; };
          const bool m = mask[grid.offset(i, j, k)] != 0;
          if (strictly(i) && strictly(j) && strictly(k)) {
            EXPECT_TRUE(m) << i << " " << j << " " << k;
          }
          if (outside(i) || outside(j) || outside(k)) {
            EXPECT_FALSE(m) << i << " " << j << " " << k;
          }
        }
  }
}

}  // namespace
}  // namespace tfd::core
