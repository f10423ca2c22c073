// Regions that are topological balls (paper §6.1): the simple-tet test (core/region/tet_set.h),
// the independent ball check (core/region/ball_check.h) and region growing
// (core/region/ball_region.h), each checked against the other and on sets whose topology is
// known (tori, shells, separate pieces).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/region/region_vertices.h"
#include "core/region/tet_set.h"
#include "tests/core/design/curve_test_meshes.h"

namespace tfd::core {
namespace {

Vec3 centroid(const TetMesh& m, int t) {
  const auto& v = m.tets()[t];
  return 0.25 *
         (m.positions()[v[0]] + m.positions()[v[1]] + m.positions()[v[2]] + m.positions()[v[3]]);
}

std::vector<int> tetsWhere(const TetMesh& m, const std::function<bool(const Vec3&)>& keep) {
  std::vector<int> out;
  for (int t = 0; t < int(m.tetCount()); ++t)
    if (keep(centroid(m, t))) out.push_back(t);
  return out;
}

double ringDistance(const Vec3& c, double r) {
  return std::hypot(std::hypot(c.x(), c.y()) - r, c.z());
}

TEST(BallCheck, KnowsBallsTorusShellAndPieces) {
  const auto mesh = testing::jitteredBox(10, 0.15);
  const auto ball = tetsWhere(*mesh, [](const Vec3& c) { return c.norm() < 0.5; });
  const BallCheck b = checkTopologicalBall(*mesh, ball);
  EXPECT_TRUE(b.ball) << b.problem;
  EXPECT_EQ(b.eulerCharacteristic, 2);
  EXPECT_EQ(b.surfaceFaces, 0);

  const auto torus = tetsWhere(*mesh, [](const Vec3& c) { return ringDistance(c, 0.55) < 0.25; });
  const BallCheck t = checkTopologicalBall(*mesh, torus);
  EXPECT_FALSE(t.ball);
  EXPECT_EQ(t.eulerCharacteristic, 0) << t.problem;

  const auto shell =
      tetsWhere(*mesh, [](const Vec3& c) { return c.norm() > 0.3 && c.norm() < 0.7; });
  const BallCheck s = checkTopologicalBall(*mesh, shell);
  EXPECT_FALSE(s.ball);
  EXPECT_EQ(s.boundaryComponents, 2) << s.problem;

  const auto pieces = tetsWhere(*mesh, [](const Vec3& c) {
    return (c - Vec3(0.5, 0, 0)).norm() < 0.3 || (c + Vec3(0.5, 0, 0)).norm() < 0.3;
  });
  const BallCheck p = checkTopologicalBall(*mesh, pieces);
  EXPECT_FALSE(p.ball);
  EXPECT_EQ(p.components, 2);

  // Touching the domain surface: a slab through the whole box is a ball whose boundary is
  // partly the domain surface.
  const auto slab = tetsWhere(*mesh, [](const Vec3& c) { return std::abs(c.z()) < 0.3; });
  const BallCheck sl = checkTopologicalBall(*mesh, slab);
  EXPECT_TRUE(sl.ball) << sl.problem;
  EXPECT_GT(sl.surfaceFaces, 0);
  // The whole mesh is a ball too.
  std::vector<int> all(mesh->tetCount());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_TRUE(checkTopologicalBall(*mesh, all).ball);
}

TEST(TetSet, SimpleTetTestRefusesToCloseARing) {
  const auto mesh = testing::jitteredBox(8, 0.1);
  // Walk a ring of tets: sorted by angle around the z axis, each joined when it may.
  auto ring = tetsWhere(*mesh, [](const Vec3& c) { return ringDistance(c, 0.55) < 0.2; });
  TetSet set(*mesh);
  std::size_t refused = 0;
  bool progress = true;
  set.add(ring.front());
  while (progress) {
    progress = false;
    for (int t : ring) {
      if (set.contains(t)) continue;
      if (set.sharedFaces(t) == 0) continue;
      if (set.canAdd(t)) set.add(t), progress = true;
    }
  }
  for (int t : ring) refused += !set.contains(t);
  EXPECT_GT(refused, 0u) << "a ring cannot be grown as a ball by simple tets alone";
  const BallCheck check = checkTopologicalBall(*mesh, set.tets());
  EXPECT_TRUE(check.ball) << check.problem;
  // A tet touching the set only at a vertex or an edge may not join.
  TetSet one(*mesh);
  one.add(0);
  for (int t = 1; t < int(mesh->tetCount()); ++t) {
    const auto& a = mesh->tets()[0];
    const auto& b = mesh->tets()[t];
    int shared = 0;
    for (int v : b) shared += std::count(a.begin(), a.end(), v);
    EXPECT_EQ(one.canAdd(t), shared == 3) << "tet " << t << " shares " << shared << " vertices";
  }
}

/// 100 random runs: random seeds, random forbidden tets and distances, then random simple
/// additions and removals; every result must pass the independent check.
TEST(BallRegion, HundredRandomGrowShrinkRunsAreBalls) {
  const auto mesh = testing::carvedBall(9);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> anyTet(0, int(mesh->tetCount()) - 1);
  std::uniform_real_distribution<double> u(0, 1);
  int incomplete = 0;
  for (int run = 0; run < 100; ++run) {
    std::vector<int> seeds;
    const int nSeeds = 1 + run % 5;
    for (int i = 0; i < nSeeds; ++i) seeds.push_back(anyTet(rng));
    std::vector<unsigned char> forbidden(mesh->tetCount(), 0);
    for (int i = 0; i < 20; ++i) forbidden[anyTet(rng)] = 1;
    for (int s : seeds) forbidden[s] = 0;
    const double distance = 0.5 * u(rng);
    const BallRegion r = growBallRegion(*mesh, seeds, forbidden, {distance});
    if (!r.complete) {
      ++incomplete;
      continue;
    }
    const BallCheck check = checkTopologicalBall(*mesh, r.tets);
    ASSERT_TRUE(check.ball) << "run " << run << ": " << check.problem;
    for (int s : seeds) EXPECT_TRUE(std::binary_search(r.tets.begin(), r.tets.end(), s));
    for (int t : r.tets) EXPECT_FALSE(forbidden[t]) << "run " << run;
    // Random simple moves keep it a ball.
    TetSet set(*mesh);
    for (int t : r.tets) set.add(t);
    for (int step = 0; step < 300; ++step) {
      const int t = anyTet(rng);
      const bool removing = set.contains(t);
      if (removing ? set.canRemove(t) : set.canAdd(t)) {
        removing ? set.remove(t) : set.add(t);
        const BallCheck now = checkTopologicalBall(*mesh, set.tets());
        ASSERT_TRUE(now.ball) << "run " << run << " step " << step
                              << (removing ? " removing " : " adding ") << t << " shared faces "
                              << set.sharedFaces(t) << ": " << now.problem;
      }
    }
    const BallCheck after = checkTopologicalBall(*mesh, set.tets());
    ASSERT_TRUE(after.ball) << "run " << run << " after random moves: " << after.problem;
  }
  EXPECT_LT(incomplete, 10);
}

TEST(BallRegion, ARingOfSeedsGetsItsDiskFilledAndGrowOutStaysWithinTheDistance) {
  const auto mesh = testing::jitteredBox(12, 0.15);
  const auto ring = tetsWhere(*mesh, [](const Vec3& c) { return ringDistance(c, 0.45) < 0.09; });
  ASSERT_GT(ring.size(), 20u);
  const std::vector<unsigned char> none(mesh->tetCount(), 0);
  const BallRegion core = growBallRegion(*mesh, ring, none, {0});
  ASSERT_TRUE(core.complete) << core.growStop;
  EXPECT_TRUE(checkTopologicalBall(*mesh, core.tets).ball);
  EXPECT_LE(core.shrunkTets, core.grownTets);
  const double d = 0.3;
  const BallRegion grown = growBallRegion(*mesh, ring, none, {d});
  ASSERT_TRUE(grown.complete);
  EXPECT_TRUE(checkTopologicalBall(*mesh, grown.tets).ball);
  EXPECT_GT(grown.tets.size(), core.tets.size());
  EXPECT_TRUE(
      std::includes(grown.tets.begin(), grown.tets.end(), core.tets.begin(), core.tets.end()));
  for (int t : grown.tets) {
    if (std::binary_search(core.tets.begin(), core.tets.end(), t)) continue;
    double best = 1e9;
    for (int c : core.tets) best = std::min(best, (centroid(*mesh, t) - centroid(*mesh, c)).norm());
    EXPECT_LE(best, d + 1e-12) << "tet " << t;
  }
}

TEST(BallRegion, ALineThroughTheRingBlocksIt) {
  const auto mesh = testing::jitteredBox(12, 0.15);
  const auto ring = tetsWhere(*mesh, [](const Vec3& c) { return ringDistance(c, 0.45) < 0.09; });
  std::vector<unsigned char> forbidden(mesh->tetCount(), 0);
  for (int t : tetsWhere(*mesh, [](const Vec3& c) { return std::hypot(c.x(), c.y()) < 0.1; }))
    forbidden[t] = 1;
  const BallRegion r = growBallRegion(*mesh, ring, forbidden, {0.3});
  EXPECT_FALSE(r.complete);
  EXPECT_FALSE(r.missingSeeds.empty());
  ASSERT_GE(r.blockingTet, 0);
  EXPECT_TRUE(forbidden[r.blockingTet]);
  EXPECT_NE(r.growStop.find("hold another curve"), std::string::npos) << r.growStop;
}

TEST(BallRegion, ALineAcrossTheBoxMakesARegionOnTheDomainSurfaceWithFreeSurfaceVertices) {
  const auto mesh = testing::jitteredBox(10, 0.15);
  const auto line =
      tetsWhere(*mesh, [](const Vec3& c) { return std::hypot(c.x() - 0.1, c.y() + 0.05) < 0.1; });
  const BallRegion r =
      growBallRegion(*mesh, line, std::vector<unsigned char>(mesh->tetCount(), 0), {0.2});
  ASSERT_TRUE(r.complete);
  const BallCheck check = checkTopologicalBall(*mesh, r.tets);
  EXPECT_TRUE(check.ball) << check.problem;
  EXPECT_GT(check.surfaceFaces, 0);
  const RegionVertices rv = regionVertices(*mesh, r.tets);
  EXPECT_GT(rv.freeOnSurface, 0u);
  EXPECT_GT(rv.surfaceFaces, 0u);
  EXPECT_GT(rv.heldFaces, 0u);
  // Held: exactly the region vertices with a tet outside.
  const auto in = tetFlags(*mesh, r.tets);
  for (int v : rv.vertices) {
    bool outside = false;
    for (int t : mesh->vertexTets(v)) outside = outside || !in[t];
    EXPECT_EQ(bool(rv.held[v]), outside);
  }
  EXPECT_EQ(rv.free.size() + std::count(rv.held.begin(), rv.held.end(), 1), rv.vertices.size());
  // Its parallel passes give what one direct pass gives, with one thread or several.
  std::size_t surface = 0, heldFaces = 0, freeOnSurface = 0;
  for (int t : r.tets)
    for (int f : mesh->tetFaces()[t]) {
      const auto& ft = mesh->faceTets()[f];
      const int other = ft[0] == t ? ft[1] : ft[0];
      surface += other < 0;
      heldFaces += other >= 0 && !in[other];
    }
  std::vector<int> free;
  for (int v : rv.vertices)
    if (!rv.held[v]) free.push_back(v), freeOnSurface += mesh->isBoundaryVertex(v);
  EXPECT_EQ(rv.surfaceFaces, surface);
  EXPECT_EQ(rv.heldFaces, heldFaces);
  EXPECT_EQ(rv.freeOnSurface, freeOnSurface);
  EXPECT_EQ(rv.free, free);
  EXPECT_TRUE(std::is_sorted(rv.vertices.begin(), rv.vertices.end()));
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const RegionVertices single = regionVertices(*mesh, r.tets);
  EXPECT_EQ(single.vertices, rv.vertices);
  EXPECT_EQ(single.held, rv.held);
  EXPECT_EQ(single.surfaceFaces, rv.surfaceFaces);
  EXPECT_EQ(single.heldFaces, rv.heldFaces);
}

}  // namespace
}  // namespace tfd::core

namespace tfd::core {
namespace {

/// Each forbidden tet met is counted once: the count in growOutStop is at most the number of
/// distinct forbidden tets next to the region (a forbidden tet re-queued whenever a tet around
/// one of its vertices joined used to be counted again each time).
// The shrink tests a refused tet again only after a tet beside it left, and drops the tets
// that left from its list: the removals must be those of the plain rule, every listed tet
// still in the set tested in every sweep, farthest first.
TEST(BallRegion, ShrinkRemovesWhatTestingEveryTetInEverySweepRemoves) {
  const auto mesh = testing::jitteredBox(7, 0.15);
  const TetMesh& m = *mesh;
  std::mt19937 rng(11);
  int removedInAll = 0;
  for (int run = 0; run < 12; ++run) {
    // A ball: tets added in a random breadth-first order while the simple-tet test allows.
    std::vector<int> added;
    {
      TetSet grow(m);
      std::vector<int> front{int(rng() % m.tetCount())};
      std::vector<char> seen(m.tetCount(), 0);
      seen[front[0]] = 1;
      const std::size_t target = m.tetCount() / 3 + rng() % (m.tetCount() / 2);
      while (!front.empty() && grow.size() < target) {
        const std::size_t pick = rng() % front.size();
        const int t = front[pick];
        front.erase(front.begin() + pick);
        if (!grow.canAdd(t)) continue;
        grow.add(t), added.push_back(t);
        for (int n : grow.neighbours(t))
          if (n >= 0 && !seen[n]) seen[n] = 1, front.push_back(n);
      }
    }
    // Keys with many ties (broken by id), a few tets kept as seeds (not listed).
    std::vector<std::pair<double, int>> keyed;
    for (int t : added)
      if (rng() % 10 != 0) keyed.emplace_back(double(rng() % 7), t);
    TetSet fast(m), plain(m);
    for (int t : added) fast.add(t), plain.add(t);
    shrinkBall(fast, keyed);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (int sweep = 0; sweep < 64; ++sweep) {
      bool any = false;
      for (const auto& [key, t] : keyed)
        if (plain.contains(t) && plain.canRemove(t)) plain.remove(t), any = true;
      if (!any) break;
    }
    ASSERT_EQ(fast.tets(), plain.tets()) << "run " << run;
    removedInAll += int(added.size() - plain.size());
    EXPECT_TRUE(checkTopologicalBall(m, plain.tets()).ball) << "run " << run;
  }
  EXPECT_GT(removedInAll, 1000);
}

TEST(BallRegion, ForbiddenTetsLeftOutAreCountedOnce) {
  const auto mesh = testing::jitteredBox(12, 0.15);
  const auto seeds = tetsWhere(*mesh, [](const Vec3& c) { return c.norm() < 0.15; });
  std::vector<unsigned char> forbidden(mesh->tetCount(), 0);
  for (int t : tetsWhere(*mesh, [](const Vec3& c) { return c.x() > 0.3 && c.x() < 0.42; }))
    forbidden[t] = 1;
  const BallRegion r = growBallRegion(*mesh, seeds, forbidden, {0.7});
  ASSERT_TRUE(r.complete) << r.growStop;
  std::vector<unsigned char> in(mesh->tetCount(), 0);
  for (int t : r.tets) in[t] = 1;
  std::vector<unsigned char> next(mesh->tetCount(), 0);
  int adjacent = 0;
  for (int t : r.tets)
    for (int f : mesh->tetFaces()[t])
      for (int n : mesh->faceTets()[f])
        if (n >= 0 && forbidden[n] && !next[n]) next[n] = 1, ++adjacent;
  const std::string marker = " tets left out because they hold another curve";
  const auto at = r.growOutStop.find(marker);
  ASSERT_NE(at, std::string::npos) << r.growOutStop;
  const auto begin = r.growOutStop.rfind("; ", at);
  const int reported = std::stoi(r.growOutStop.substr(begin + 2, at - begin - 2));
  EXPECT_GT(reported, 0);
  EXPECT_LE(reported, adjacent) << r.growOutStop;
}

}  // namespace
}  // namespace tfd::core

namespace tfd::core {
namespace {

/// The simple-tet test spelled out in full (every vertex and edge of t held elsewhere must lie
/// on a face of the contact), against which TetSet's one-count test is checked.
bool fullContactIsDisk(const TetMesh& m, int t, const std::vector<char>& faceIn,
                       const std::function<bool(int)>& vertexHeld,
                       const std::function<bool(int, int)>& edgeHeld) {
  int count = 0;
  for (int i = 0; i < 4; ++i) count += faceIn[i];
  if (count == 0 || count == 4) return false;
  for (int i = 0; i < 4; ++i) {
    bool covered = false;
    for (int j = 0; j < 4; ++j) covered = covered || (j != i && faceIn[j]);
    if (vertexHeld(m.tets()[t][i]) && !covered) return false;
    for (int k = i + 1; k < 4; ++k) {
      bool edgeCovered = false;
      for (int j = 0; j < 4; ++j) edgeCovered = edgeCovered || (j != i && j != k && faceIn[j]);
      if (edgeHeld(i, k) && !edgeCovered) return false;
    }
  }
  return true;
}

TEST(TetSet, OneCountTestEqualsTheFullVertexAndEdgeTest) {
  const auto mesh = testing::jitteredBox(6, 0.15);
  const TetMesh& m = *mesh;
  std::mt19937 rng(5);
  int adds = 0, removes = 0;
  for (int run = 0; run < 40; ++run) {
    TetSet set(m);
    std::vector<char> in(m.tetCount(), 0);
    const double density = 0.1 + 0.8 * (run % 8) / 8.0;
    for (int t = 0; t < int(m.tetCount()); ++t)
      if (std::uniform_real_distribution<double>(0, 1)(rng) < density) set.add(t), in[t] = 1;
    if (run % 2) set.countAllEdges();  // the tets around every edge counted at once, not lazily
    auto around = [&](int a, int b, bool wantIn, int skip) {  // tets around vertex/edge
      for (int n : m.vertexTets(a)) {
        if (n == skip) continue;
        const auto& v = m.tets()[n];
        if (b >= 0 && std::find(v.begin(), v.end(), b) == v.end()) continue;
        if (bool(in[n]) == wantIn) return true;
      }
      return false;
    };
    for (int t = 0; t < int(m.tetCount()); ++t) {
      std::vector<char> faceIn(4), faceOut(4);
      for (int i = 0; i < 4; ++i) {
        const auto& ft = m.faceTets()[m.tetFaces()[t][i]];
        const int other = ft[0] == t ? ft[1] : ft[0];
        faceIn[i] = other >= 0 && in[other];
        faceOut[i] = other < 0 || !in[other];
      }
      const auto& v = m.tets()[t];
      const bool inner = fullContactIsDisk(
          m, t, faceIn, [&](int x) { return around(x, -1, true, t); },
          [&](int i, int k) { return around(v[i], v[k], true, t); });
      if (!in[t]) {
        ASSERT_EQ(set.canAdd(t), inner) << "run " << run << " tet " << t;
        ++adds;
        continue;
      }
      // The complement: tets outside the set, or the outside of the domain.
      const bool outer = fullContactIsDisk(
          m, t, faceOut, [&](int x) { return m.isBoundaryVertex(x) || around(x, -1, false, t); },
          [&](int i, int k) {
            bool surface = false;
            for (int f : m.boundaryFaces()) {
              const auto& fv = m.faces()[f];
              surface = surface || (std::find(fv.begin(), fv.end(), v[i]) != fv.end() &&
                                    std::find(fv.begin(), fv.end(), v[k]) != fv.end());
            }
            return surface || around(v[i], v[k], false, t);
          });
      ASSERT_EQ(set.canRemove(t), set.size() > 1 && inner && outer)
          << "run " << run << " tet " << t;
      ++removes;
    }
  }
  EXPECT_GT(adds, 1000);
  EXPECT_GT(removes, 1000);
}

}  // namespace
}  // namespace tfd::core
