// Connecting the degenerate points on the faces of one tet (core/topology/tet_connection.h,
// algorithms note §4): with the face points found by brute force (Gauss–Newton on the
// Zheng–Pang functions, independent of the extractor), every point is joined exactly once and
// every joining arc runs inside the tet on degenerate tensors of the independently evaluated
// field; a wrong pairing would leave the tet. Tets with four points are among the cases.
#include "core/topology/tet_connection.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "tests/core/topology/tet_field_checks.h"

namespace tfd::core::topology {
namespace {

using testing::isolatedEigenvector;
using testing::relativeGap;
using testing::TetData;

/// The face points of one tet, in world coordinates, with ids from a map shared by the tets
/// (a face's points get the same ids in both of its tets).
std::vector<TetNode> facePoints(const TetData& t, const std::array<int, 4>& vertexIds,
                                std::map<std::array<int, 3>, std::vector<TetNode>>& known,
                                int& nextId) {
  std::vector<TetNode> nodes;
  for (int opposite = 0; opposite < 4; ++opposite) {
    std::array<int, 3> local{}, global{};
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != opposite) local[k] = i, global[k++] = vertexIds[i];
    // Sort by global id so both tets see the face the same way.
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b)
        if (global[b] < global[a]) std::swap(global[a], global[b]), std::swap(local[a], local[b]);
    auto it = known.find(global);
    if (it == known.end()) {
      std::vector<TetNode> found;
      for (const Vec3& bary : testing::bruteForceFacePoints(
               t.tensors[local[0]], t.tensors[local[1]], t.tensors[local[2]])) {
        TetNode n;
        n.id = nextId++;
        n.position = bary[0] * t.corners[local[0]] + bary[1] * t.corners[local[1]] +
                     bary[2] * t.corners[local[2]];
        n.eigenvector = isolatedEigenvector(t.at(n.position)).vector;
        n.faceInterior = bary.minCoeff() > 1e-9;
        found.push_back(n);
      }
      it = known.emplace(global, found).first;
    }
    nodes.insert(nodes.end(), it->second.begin(), it->second.end());
  }
  return nodes;
}

TEST(TetConnection, JoinsFacePointsByArcsInsideTheTetOnTheDegenerateSet) {
  int tetsWithPoints = 0, tetsWithFour = 0, segments = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const auto mesh = testing::jitteredBox(2, -1, 1, 0.2, seed);
    std::mt19937_64 rng(seed);
    const testing::LinearField lf = testing::randomLinearField(rng);
    std::map<std::array<int, 3>, std::vector<TetNode>> known;
    int nextId = 0;
    for (const auto& tet : mesh->tets()) {
      TetData t;
      for (int i = 0; i < 4; ++i) {
        t.corners[i] = mesh->positions()[tet[i]];
        t.tensors[i] = lf(t.corners[i]).deviator();
      }
      const std::vector<TetNode> nodes = facePoints(t, tet, known, nextId);
      if (nodes.empty()) continue;
      ++tetsWithPoints;
      tetsWithFour += nodes.size() >= 4;
      const TetLinearField field(t.corners, t.tensors);
      const TetConnection c = connectTet(field, nodes, 3);
      EXPECT_EQ(c.flags, 0u) << "seed " << seed << ", " << nodes.size() << " points";
      ASSERT_EQ(c.segments.size() * 2, nodes.size());
      std::map<int, int> uses;
      for (const TetSegment& s : c.segments) {
        ++uses[s.from], ++uses[s.to];
        EXPECT_TRUE(s.exactArc);
        ASSERT_FALSE(s.arc.interior.empty());
        for (const ArcPoint& p : s.arc.interior) {
          EXPECT_GT(t.barycentric(p.position).minCoeff(), -1e-9) << "the arc leaves the tet";
          EXPECT_LT(relativeGap(t.at(p.position)), 1e-7);
        }
        // The arc's ends are its nodes: its first and last samples lie between them.
        ++segments;
      }
      for (const TetNode& n : nodes) EXPECT_EQ(uses[n.id], 1) << "node " << n.id;
    }
  }
  EXPECT_GT(tetsWithPoints, 20);
  EXPECT_GT(tetsWithFour, 0) << "pairing more than two points is exercised";
  EXPECT_GT(segments, 20);
}

TEST(TetConnection, OnePointIsOddAndANonGenericFieldIsPairedHeuristically) {
  std::mt19937_64 rng(5);
  TetData t = testing::randomTet(rng);
  const TetLinearField generic(t.corners, t.tensors);
  TetNode a;
  a.id = 7;
  a.position = Vec3(0.4, 0.3, 0);
  EXPECT_EQ(connectTet(generic, std::span<const TetNode>(&a, 1), 0).flags, unsigned(kTetOdd));
  a.faceInterior = false;  // a point on an edge may touch the tet without entering it
  EXPECT_EQ(connectTet(generic, std::span<const TetNode>(&a, 1), 0).flags, 0u);
  // Constant field (no conic): four points are paired by distance, flagged.
  for (auto& x : t.tensors) x = t.tensors[0];
  const TetLinearField constant(t.corners, t.tensors);
  std::vector<TetNode> nodes(4);
  const Vec3 p[4] = {Vec3(0.1, 0.1, 0), Vec3(0.15, 0.1, 0), Vec3(0.8, 0.1, 0.01),
                     Vec3(0.75, 0.12, 0)};
  for (int i = 0; i < 4; ++i) nodes[i].id = 10 + i, nodes[i].position = p[i];
  const TetConnection c = connectTet(constant, nodes, 0);
  EXPECT_TRUE(c.flags & kTetHeuristic);
  EXPECT_TRUE(c.flags & kTetNonGeneric);
  ASSERT_EQ(c.segments.size(), 2u);
  std::set<std::pair<int, int>> pairs;
  for (const auto& s : c.segments) pairs.insert({std::min(s.from, s.to), std::max(s.from, s.to)});
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{{10, 11}, {12, 13}}));
}

}  // namespace
}  // namespace tfd::core::topology
