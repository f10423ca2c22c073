#include "core/surface/surface_orient.h"

#include <gtest/gtest.h>

#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

/// `count` regular octahedra side by side along x (separate pieces), counter-clockwise seen
/// from outside.
SurfaceMesh octahedra(int count) {
  SurfaceMesh m;
  const std::array<std::array<int, 3>, 8> faces{
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  for (int c = 0; c < count; ++c) {
    const int base = int(m.positions.size());
    const double x = 3.0 * c;
    m.positions.insert(
        m.positions.end(),
        {{x + 1, 0, 0}, {x - 1, 0, 0}, {x, 1, 0}, {x, -1, 0}, {x, 0, 1}, {x, 0, -1}});
    for (auto f : faces) m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
  }
  return m;
}

void reverse(SurfaceMesh& m, int t) { std::swap(m.triangles[t][1], m.triangles[t][2]); }

TEST(SurfaceOrient, ReversesTheFewTrianglesThatDisagreeWithTheirPiece) {
  const SurfaceMesh good = octahedra(2);
  SurfaceMesh m = good;
  reverse(m, 1), reverse(m, 6), reverse(m, 8 + 3);  // two in the first piece, one in the second
  ASSERT_FALSE(closedSurfaceProblems(m).empty());
  const OrientReport r = orientConsistently(m);
  EXPECT_TRUE(r.applied);
  EXPECT_FALSE(r.oneSided);
  EXPECT_EQ(r.flippedTriangles, 3u);
  EXPECT_EQ(m.triangles, good.triangles) << "exactly the reversed ones are restored";
  EXPECT_TRUE(closedSurfaceProblems(m).empty());
  EXPECT_NEAR(enclosedVolume(m), 2 * 4.0 / 3.0, 1e-12);
}

TEST(SurfaceOrient, KeepsTheOrientationMostOfAPieceHas) {
  // Inside out but for one triangle: that one is reversed, not the seven others.
  SurfaceMesh m = octahedra(1);
  for (int t = 1; t < 8; ++t) reverse(m, t);
  const OrientReport r = orientConsistently(m);
  EXPECT_EQ(r.flippedTriangles, 1u);
  EXPECT_TRUE(closedSurfaceProblems(m).empty());
  EXPECT_NEAR(enclosedVolume(m), -4.0 / 3.0, 1e-12) << "inside out, as the file mostly says";
}

TEST(SurfaceOrient, LeavesAConsistentSurfaceUnchanged) {
  SurfaceMesh m = octahedra(3);
  const SurfaceMesh before = m;
  const OrientReport r = orientConsistently(m);
  EXPECT_TRUE(r.applied);
  EXPECT_EQ(r.flippedTriangles, 0u);
  EXPECT_EQ(m.triangles, before.triangles);
}

TEST(SurfaceOrient, ReportsAOneSidedSurfaceAndChangesNothing) {
  // The six-vertex projective plane (hemi-icosahedron): every edge on two triangles, and no
  // choice of orientations agrees across all of them.
  SurfaceMesh m;
  m.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                 {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
  const SurfaceMesh before = m;
  const OrientReport r = orientConsistently(m);
  EXPECT_FALSE(r.applied);
  EXPECT_TRUE(r.oneSided);
  EXPECT_EQ(m.triangles, before.triangles);
}

TEST(SurfaceOrient, LeavesAnOpenSurfaceForTheCheckToName) {
  SurfaceMesh m = octahedra(1);
  m.triangles.pop_back();
  reverse(m, 0);
  const SurfaceMesh before = m;
  const OrientReport r = orientConsistently(m);
  EXPECT_FALSE(r.applied);
  EXPECT_FALSE(r.oneSided);
  EXPECT_EQ(m.triangles, before.triangles);
}

}  // namespace
}  // namespace tfd::core
