#include "core/surface/surface_holes.h"

#include <gtest/gtest.h>

#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

/// A regular octahedron, counter-clockwise seen from outside.
SurfaceMesh octahedron() {
  SurfaceMesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

TEST(SurfaceHoles, AMissingTriangleIsALoopRunInTheFillingDirection) {
  SurfaceMesh m = octahedron();
  m.triangles.erase(m.triangles.begin() + 1);  // {2, 1, 4}
  const auto loops = holeLoops(m);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0], (std::vector<int>{1, 4, 2})) << "from its smallest vertex, as {2, 1, 4} ran";
  const HoleFilling f = fillHoles(m, 3);
  EXPECT_EQ(f.filled, 1u);
  EXPECT_EQ(f.triangles, 1u);
  EXPECT_EQ(m.positions.size(), 6u) << "a triangle needs no new vertex";
  EXPECT_TRUE(closedSurfaceProblems(m).empty());
  EXPECT_NEAR(enclosedVolume(m), 4.0 / 3.0, 1e-15);
}

TEST(SurfaceHoles, LongerHolesGetAFanOrAreLeftWhenLongerThanAsked) {
  SurfaceMesh m = octahedron();
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 2);  // two sharing edge (2, 4)
  ASSERT_EQ(holeLoops(m).size(), 1u);
  EXPECT_EQ(holeLoops(m)[0].size(), 4u);
  SurfaceMesh left = m;
  const HoleFilling none = fillHoles(left, 3);
  EXPECT_EQ(none.filled, 0u);
  EXPECT_EQ(none.skipped, 1u);
  EXPECT_EQ(none.largest, 4u);
  EXPECT_EQ(left.triangles.size(), m.triangles.size());
  const HoleFilling f = fillHoles(m, 4);
  EXPECT_EQ(f.filled, 1u);
  EXPECT_EQ(f.triangles, 4u);
  ASSERT_EQ(m.positions.size(), 7u);
  EXPECT_TRUE(m.positions[6].isApprox(Vec3(0, 0.25, 0.25))) << "the mean of the hole's corners";
  EXPECT_TRUE(closedSurfaceProblems(m).empty()) << "closed, and oriented like its neighbours";
  EXPECT_GT(enclosedVolume(m), 0);
}

TEST(SurfaceHoles, ABoundaryThatTouchesItselfHasNoLoops) {
  SurfaceMesh m;  // two triangles sharing only vertex 0
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_TRUE(holeLoops(m).empty());
  EXPECT_EQ(fillHoles(m, 100).filled, 0u);
  EXPECT_TRUE(holeLoops(octahedron()).empty()) << "closed";
}

}  // namespace
}  // namespace tfd::core
