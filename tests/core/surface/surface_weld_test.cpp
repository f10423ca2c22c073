#include "core/surface/surface_weld.h"

#include <gtest/gtest.h>

namespace tfd::core {
namespace {

TEST(SurfaceWeld, MergesExactDuplicatesKeepsOrderAndDropsCollapsedTriangles) {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},     {-0.0, 0, 0},
                 {1, 0, 0}, {0, 0, 1}, {1e-300, 0, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 3, 1}, {6, 1, 2}};
  const WeldReport r = weldCoincidentVertices(m);
  EXPECT_EQ(r.mergedVertices, 2u) << "-0 welds to +0; 1e-300 is a different position";
  EXPECT_EQ(r.droppedTriangles, 1u);
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.positions[3], Vec3(0, 0, 1));
  const std::vector<std::array<int, 3>> expected{{0, 1, 2}, {0, 1, 3}, {4, 1, 2}};
  EXPECT_EQ(m.triangles, expected);
}

TEST(SurfaceWeld, LeavesAMeshWithoutDuplicatesUnchanged) {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const SurfaceMesh before = m;
  const WeldReport r = weldCoincidentVertices(m);
  EXPECT_EQ(r.mergedVertices, 0u);
  EXPECT_EQ(m.positions, before.positions);
  EXPECT_EQ(m.triangles, before.triangles);
}

}  // namespace
}  // namespace tfd::core
