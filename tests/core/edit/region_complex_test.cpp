// The region complex (core/edit/region_complex.h) against a construction from first
// principles (std::set of the tets' vertices, edges and vertex pairs) on random tet subsets of
// a jittered box: lists, CSR adjacency and the O(1) lookups, including ids outside the region.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <random>
#include <set>

#include "core/edit/region_complex.h"
#include "core/error.h"
#include "tests/core/design/curve_test_meshes.h"

namespace tfd::core {
namespace {

TEST(RegionComplex, MatchesSetsOfTheTetsVerticesEdgesAndVertexPairs) {
  const auto mesh = testing::jitteredBox(6, 0.15);
  std::mt19937 rng(5);
  for (int run = 0; run < 20; ++run) {
    std::vector<int> tets;
    const int n = 1 + int(rng() % 300);
    for (int i = 0; i < n; ++i) tets.push_back(int(rng() % mesh->tetCount()));  // repeats too
    const RegionComplex r = regionComplex(*mesh, tets);

    const std::set<int> tetSet(tets.begin(), tets.end());
    std::set<int> vertexSet, edgeSet;
    std::set<std::pair<int, int>> pairs;  // mesh vertex pairs joined by a region edge
    for (int t : tetSet) {
      for (int v : mesh->tets()[t]) vertexSet.insert(v);
      for (int e : mesh->tetEdges()[t]) {
        edgeSet.insert(e);
        const auto& ends = mesh->edges()[e];
        pairs.insert({ends[0], ends[1]});
        pairs.insert({ends[1], ends[0]});
      }
    }
    ASSERT_EQ(r.tets, std::vector<int>(tetSet.begin(), tetSet.end()));
    ASSERT_EQ(r.vertices, std::vector<int>(vertexSet.begin(), vertexSet.end()));
    ASSERT_EQ(r.edges, std::vector<int>(edgeSet.begin(), edgeSet.end()));

    std::set<std::pair<int, int>> csr;
    for (std::size_t i = 0; i < r.vertices.size(); ++i) {
      for (int k = r.start[i]; k < r.start[i + 1]; ++k) {
        if (k > r.start[i]) {
          EXPECT_LT(r.neighbour[k - 1], r.neighbour[k]) << "ascending";
        }
        const int j = r.neighbour[k];
        csr.insert({r.vertices[i], r.vertices[j]});
        const auto& ends = mesh->edges()[r.edges[r.neighbourEdge[k]]];
        EXPECT_TRUE((ends[0] == r.vertices[i] && ends[1] == r.vertices[j]) ||
                    (ends[1] == r.vertices[i] && ends[0] == r.vertices[j]));
        EXPECT_EQ(regionEdge(r, int(i), j), r.neighbourEdge[k]);
      }
    }
    EXPECT_EQ(csr, pairs);

    for (int v = 0; v < int(mesh->vertexCount()); ++v) {
      const auto it = vertexSet.find(v);
      EXPECT_EQ(r.localVertex(v),
                it == vertexSet.end() ? -1 : int(std::distance(vertexSet.begin(), it)));
    }
    for (int e = 0; e < int(mesh->edges().size()); ++e)
      EXPECT_EQ(r.localEdge(e) >= 0, edgeSet.count(e) == 1);
    for (int t = 0; t < int(mesh->tetCount()); ++t)
      EXPECT_EQ(r.localTet(t) >= 0, tetSet.count(t) == 1);
    for (std::size_t i = 0; i < r.tets.size(); ++i) EXPECT_EQ(r.localTet(r.tets[i]), int(i));
    EXPECT_EQ(r.localVertex(-1), -1);
    EXPECT_EQ(r.localTet(int(mesh->tetCount())), -1);
  }
  EXPECT_THROW(regionComplex(*mesh, {}), Error);
  EXPECT_THROW(regionComplex(*mesh, {0, int(mesh->tetCount())}), Error);
}

bool sameComplex(const RegionComplex& a, const RegionComplex& b) {
  return a.tets == b.tets && a.vertices == b.vertices && a.edges == b.edges && a.start == b.start &&
         a.neighbour == b.neighbour && a.neighbourEdge == b.neighbourEdge;
}

// An ascending region (as region growing gives) of most of the mesh takes the path without the
// sort: the same complex as from a shuffled list with repeats, and the same for one and two
// threads (the adjacency is placed in parallel, in any order, then sorted).
TEST(RegionComplex, LargeAscendingRegionMatchesAShuffledListAndOneThread) {
  const auto mesh = testing::jitteredBox(14, 0.15);
  std::vector<int> ascending;
  for (int t = 0; t < int(mesh->tetCount()); ++t)
    if (t % 7 != 3) ascending.push_back(t);
  std::vector<int> shuffled = ascending;
  shuffled.insert(shuffled.end(), ascending.begin(), ascending.begin() + 500);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(8));
  const RegionComplex fast = regionComplex(*mesh, ascending);
  EXPECT_TRUE(sameComplex(fast, regionComplex(*mesh, shuffled)));
  const RegionComplex single = [&] {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    return regionComplex(*mesh, ascending);
  }();
  EXPECT_TRUE(sameComplex(fast, single));
  for (std::size_t i = 0; i < fast.tets.size(); ++i) ASSERT_EQ(fast.localTet(fast.tets[i]), int(i));
  EXPECT_EQ(fast.localTet(3), -1);
}

}  // namespace
}  // namespace tfd::core
