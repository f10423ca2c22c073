// Chaining per-tet segments into curves (core/topology/curve_assembly.h, algorithms note §4–5)
// on hand-built node graphs whose answer is known: an open chain between two boundary points,
// a loop, a junction, a dangling end, a curve of mixed type, and the per-point patterns from
// the arc ends (wedge, trisector, transition where δ changes sign at a node).
#include "core/topology/curve_assembly.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tfd::core::topology {
namespace {

CurveNode node(double x, double y, double sigma = 1, bool boundary = false, int face = -1) {
  CurveNode n;
  n.position = Vec3(x, y, 0);
  n.eigenvector = Vec3::UnitZ();
  n.sigma = sigma;
  n.onBoundary = boundary;
  n.source = {PointSource::Kind::Face, face};
  return n;
}

/// A segment whose arc has the given δ cosines at its ends (tangents along the chord).
AssemblySegment segment(const std::vector<CurveNode>& nodes, int from, int to, int tet,
                        double cosineFrom = 0.5, double cosineTo = 0.5) {
  AssemblySegment s;
  s.from = from, s.to = to, s.tet = tet;
  const Vec3 d = (nodes[to].position - nodes[from].position).normalized();
  s.arc.start = {cosineFrom, d};
  s.arc.end = {cosineTo, d};
  return s;
}

const DegenerateCurve* curveStartingAt(const AssemblyResult& r, const Vec3& p) {
  for (const auto& c : r.curves)
    if (c.points.front() == p || c.points.back() == p) return &c;
  return nullptr;
}

TEST(CurveAssembly, OpenChainBetweenBoundaryPointsInNodeOrder) {
  // 0 - 1 - 2 - 3, segments given out of order and in both directions.
  std::vector<CurveNode> nodes = {node(0, 0, 1, true, 10), node(1, 0, 1, false, 11),
                                  node(2, 0.5, 1, false, 12), node(3, 0, 1, true, 13)};
  std::vector<AssemblySegment> segs = {segment(nodes, 2, 1, 101), segment(nodes, 0, 1, 100),
                                       segment(nodes, 2, 3, 102)};
  const AssemblyResult r = assembleCurves(nodes, segs);
  ASSERT_EQ(r.curves.size(), 1u);
  const DegenerateCurve& c = r.curves[0];
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.type, DegenerateType::Linear);
  ASSERT_EQ(c.points.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(c.points[i], nodes[i].position);  // the walk starts at the lowest end node
    EXPECT_EQ(c.sources[i].id, 10 + i);
    EXPECT_EQ(c.patterns[i], DegeneratePattern::Wedge);
    if (i < 3) {
      EXPECT_GT(c.tangents[i].dot(nodes[i + 1].position - nodes[i].position), 0);
    }
  }
  EXPECT_EQ(r.danglingEnds, 0);
  EXPECT_EQ(r.junctions, 0);
  EXPECT_EQ(r.mixedTypeCurves, 0);
}

TEST(CurveAssembly, LoopIsClosedWithoutRepeatingItsFirstPoint) {
  std::vector<CurveNode> nodes = {node(0, 0, -1), node(1, 0, -1), node(1, 1, -1), node(0, 1, -1)};
  std::vector<AssemblySegment> segs = {
      segment(nodes, 0, 1, 0, -0.3, -0.3), segment(nodes, 2, 1, 1, -0.3, -0.3),
      segment(nodes, 2, 3, 2, -0.3, -0.3), segment(nodes, 3, 0, 3, -0.3, -0.3)};
  const AssemblyResult r = assembleCurves(nodes, segs);
  ASSERT_EQ(r.curves.size(), 1u);
  const DegenerateCurve& c = r.curves[0];
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.type, DegenerateType::Planar);
  ASSERT_EQ(c.points.size(), 4u);
  for (auto p : c.patterns) EXPECT_EQ(p, DegeneratePattern::Trisector);
  // Consecutive points are joined by a segment.
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR((c.points[i] - c.points[(i + 1) % 4]).norm(), 1, 1e-15);
  EXPECT_EQ(r.danglingEnds, 0);
}

TEST(CurveAssembly, JunctionsSplitCurvesAndDanglingEndsAreCounted) {
  // A "Y": node 0 meets three branches ending at 1 (boundary), 2 (boundary) and 3 (inside).
  std::vector<CurveNode> nodes = {node(0, 0), node(-1, 1, 1, true), node(1, 1, 1, true),
                                  node(0, -1)};
  std::vector<AssemblySegment> segs = {segment(nodes, 0, 1, 0), segment(nodes, 0, 2, 1),
                                       segment(nodes, 3, 0, 2)};
  const AssemblyResult r = assembleCurves(nodes, segs);
  EXPECT_EQ(r.junctions, 1);
  ASSERT_EQ(r.curves.size(), 3u);
  for (const auto& c : r.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.points.size(), 2u);
  }
  // Ends not on the boundary: node 0 three times (each branch ends there) and node 3 once.
  EXPECT_EQ(r.danglingEnds, 4);
}

TEST(CurveAssembly, TypeIsTheMajorityAndMixedCurvesAreCounted) {
  std::vector<CurveNode> nodes = {node(0, 0, -1, true), node(1, 0, 1), node(2, 0, -1),
                                  node(3, 0, -1, true)};
  std::vector<AssemblySegment> segs = {segment(nodes, 0, 1, 0), segment(nodes, 1, 2, 1),
                                       segment(nodes, 2, 3, 2)};
  const AssemblyResult r = assembleCurves(nodes, segs);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.curves[0].type, DegenerateType::Planar);
  EXPECT_EQ(r.mixedTypeCurves, 1);
}

TEST(CurveAssembly, PatternsComeFromTheArcEndsAndArcPointsAreInserted) {
  // δ > 0 on the first segment, < 0 on the second: the shared node is a transition point;
  // an arc's interior points come in travel order, reversed for a segment walked backwards.
  std::vector<CurveNode> nodes = {node(0, 0, 1, true), node(1, 0), node(2, 0, 1, true)};
  std::vector<AssemblySegment> segs = {segment(nodes, 0, 1, 5, 0.4, 0.4),
                                       segment(nodes, 2, 1, 6, -0.4, -0.4)};
  for (double x : {1.75, 1.5, 1.25}) {  // stored from node 2 towards node 1
    ArcPoint p;
    p.theta = 2 - x;
    p.position = Vec3(x, 0.1, 0);
    p.tangent = Vec3(-1, 0, 0);
    p.cosine = -0.4;
    p.transition = x == 1.5;
    segs[1].arc.interior.push_back(p);
  }
  const AssemblyResult r = assembleCurves(nodes, segs);
  ASSERT_EQ(r.curves.size(), 1u);
  const DegenerateCurve& c = r.curves[0];
  ASSERT_EQ(c.points.size(), 6u);
  const std::vector<double> xs = {0, 1, 1.25, 1.5, 1.75, 2};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(c.points[i].x(), xs[i]) << i;
  using P = DegeneratePattern;
  EXPECT_EQ(c.patterns, (std::vector<P>{P::Wedge, P::Transition, P::Trisector, P::Transition,
                                        P::Trisector, P::Trisector}));
  for (int i = 2; i <= 4; ++i) {
    EXPECT_EQ(c.sources[i].kind, PointSource::Kind::Tet);
    EXPECT_EQ(c.sources[i].id, 6);
    EXPECT_GT(c.tangents[i].x(), 0) << "tangents follow the curve's direction";
  }
  EXPECT_GT(c.tangents[5].x(), 0);
}

TEST(CurveAssembly, DegenerateSegmentsAreIgnored) {
  std::vector<CurveNode> nodes = {node(0, 0, 1, true), node(1, 0, 1, true)};
  std::vector<AssemblySegment> segs = {segment(nodes, 0, 1, 0)};
  AssemblySegment self;
  self.from = self.to = 1;
  segs.push_back(self);
  const AssemblyResult r = assembleCurves(nodes, segs);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.curves[0].points.size(), 2u);
  EXPECT_EQ(r.junctions, 0);
  EXPECT_EQ(curveStartingAt(r, nodes[0].position), &r.curves[0]);
}

}  // namespace
}  // namespace tfd::core::topology
