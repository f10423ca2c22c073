#include "core/surface/surface_weld.h"

#include <gtest/gtest.h>

#include "core/surface/surface_check.h"

#include <limits>

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

TEST(SurfaceWeld, WeldsCloseVerticesIntoTheFirstKeptOneWithoutChaining) {
  // A row 0.9 tolerance apart: 1 joins 0, 2 is 1.8 from 0 (1 was not kept, so no chain), 3
  // joins 2. Points either side of a grid cell's face (and of 0) weld like any others.
  const double tol = 1e-3;
  SurfaceMesh m;
  m.positions = {{0, 0, 0},      {0.9e-3, 0, 0}, {1.8e-3, 0, 0},    {2.7e-3, 0, 0},   {5, 5, 5},
                 {-1e-12, 0, 0}, {5, 5, 5.0011}, {4.9999999, 5, 5}, {-5e-4, -5e-4, 0}};
  m.triangles = {{0, 1, 4}, {1, 2, 6}, {2, 3, 6}, {5, 7, 6}, {8, 2, 4}};
  const WeldReport r = weldCloseVertices(m, tol);
  // Kept: 0, 2, 4 (5 → 0, 7 → 4, 8 → 0 at 7.1e-4), 6 (1.1e-3 from 4): 5 merged.
  EXPECT_EQ(r.mergedVertices, 5u);
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[0], Vec3(0, 0, 0)) << "a kept vertex never moves";
  EXPECT_EQ(m.positions[1], Vec3(1.8e-3, 0, 0));
  EXPECT_EQ(m.positions[2], Vec3(5, 5, 5));
  EXPECT_EQ(m.positions[3], Vec3(5, 5, 5.0011));
  // {0,1,4} → {0,0,2} dropped; {2,3,6} → {1,1,3} dropped; {5,7,6} → {0,2,3}; {8,2,4} → {0,1,2}.
  EXPECT_EQ(r.droppedTriangles, 2u);
  const std::vector<std::array<int, 3>> expected{{0, 1, 3}, {0, 2, 3}, {0, 1, 2}};
  EXPECT_EQ(m.triangles, expected);
}

TEST(SurfaceWeld, ZeroToleranceWeldsExactlyRepeatedPositionsOnly) {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1e-15, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  m.triangles = {{0, 1, 3}, {2, 1, 3}};
  const WeldReport r = weldCloseVertices(m, 0);
  EXPECT_EQ(r.mergedVertices, 1u);
  EXPECT_EQ(m.positions.size(), 3u);
}

/// A closed tetrahedron whose first triangle has its own copy of vertex 0, `gap` away.
SurfaceMesh tetrahedronWithASeam(double gap) {
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {gap, 0, 0}};
  m.triangles = {{4, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}

TEST(SurfaceWeld, OpenEdgeWeldDistanceIsTheGapThatWouldCloseASeam) {
  const SurfaceMesh seam = tetrahedronWithASeam(2e-7);
  EXPECT_NEAR(openEdgeWeldDistance(seam, 1e-3), 2e-7, 1e-20);
  EXPECT_EQ(openEdgeWeldDistance(seam, 1e-7), std::numeric_limits<double>::infinity())
      << "the partners lie farther than asked for";
  SurfaceMesh closed = seam;
  weldCloseVertices(closed, 1e-6);
  EXPECT_EQ(closed.positions.size(), 4u);
  EXPECT_EQ(openEdgeWeldDistance(closed, 1e-3), 0) << "no open edge";
  SurfaceMesh open = closed;
  open.triangles.pop_back();  // a real hole: its rim's vertices are an edge length apart
  EXPECT_EQ(openEdgeWeldDistance(open, 1e-3), std::numeric_limits<double>::infinity());
}

TEST(SurfaceWeld, RepeatedTrianglesGoOppositePairsJoiningTwoSolids) {
  // Two tetrahedra on either side of the face (0, 1, 2), each closed and outward: the shared
  // face twice, facing opposite ways. A third copy of another face, facing the same way.
  SurfaceMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2},  // above the shared face
                 {0, 1, 2}, {0, 4, 1}, {1, 4, 2}, {0, 2, 4},  // below it
                 {3, 1, 2}};                                  // a copy of {1, 2, 3}
  ASSERT_FALSE(closedSurfaceProblems(m).empty());
  EXPECT_EQ(removeRepeatedTriangles(m), 3u);
  const std::vector<std::array<int, 3>> expected{{0, 1, 3}, {1, 2, 3}, {0, 3, 2},
                                                 {0, 4, 1}, {1, 4, 2}, {0, 2, 4}};
  EXPECT_EQ(m.triangles, expected) << "the first copy of a face stays, in file order";
  EXPECT_TRUE(closedSurfaceProblems(m).empty());
  EXPECT_NEAR(enclosedVolume(m), 2.0 / 6.0, 1e-15) << "one solid, both tetrahedra";
  EXPECT_EQ(removeRepeatedTriangles(m), 0u);
}

}  // namespace
}  // namespace tfd::core
