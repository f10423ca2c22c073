// TetMesh's parallel, per-vertex topology build against an independent reference (one global
// sort of all face and edge records, the construction it replaced), on meshes numbered without
// spatial coherence like TetGen's; 1 and 2 threads bitwise equal. The restoring constructor
// (stored edge and face ids, core/tet_mesh_restore.cpp) gives the same mesh and refuses ids
// that do not match the tets.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <numeric>
#include <random>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::core {
namespace {

/// A box mesh with vertices and tets renumbered at random and each tet's vertices rotated by
/// an even permutation (orientation kept): no order the build could lean on.
std::shared_ptr<const TetMesh> shuffledBox(int n, unsigned seed) {
  const auto box = makeBoxMesh(n, n + 1, n + 2, Vec3(-1, -1, -1), Vec3(1, 2, 3));
  std::mt19937 rng(seed);
  std::vector<int> perm(box->vertexCount());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Vec3> positions(perm.size());
  for (std::size_t v = 0; v < perm.size(); ++v) positions[perm[v]] = box->positions()[v];
  std::vector<TetMesh::Tet> tets;
  for (const auto& t : box->tets())
    tets.push_back({perm[t[0]], perm[t[1]], perm[t[2]], perm[t[3]]});
  std::shuffle(tets.begin(), tets.end(), rng);
  constexpr int kEven[3][4] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}};
  for (auto& t : tets) {
    const auto& e = kEven[rng() % 3];
    t = {t[e[0]], t[e[1]], t[e[2]], t[e[3]]};
  }
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

TEST(TetMeshTopology, MatchesAGlobalSortReference) {
  const auto mesh = shuffledBox(5, 11);
  const auto& tets = mesh->tets();
  // Reference: every (sorted key, tet, local) record sorted at once; ids in key order.
  constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::map<std::array<int, 2>, std::vector<std::pair<int, int>>> edges;
  std::map<std::array<int, 3>, std::vector<std::pair<int, int>>> faces;
  for (int t = 0; t < int(tets.size()); ++t) {
    for (int i = 0; i < 6; ++i) {
      std::array<int, 2> k = {tets[t][kEdge[i][0]], tets[t][kEdge[i][1]]};
      std::sort(k.begin(), k.end());
      edges[k].push_back({t, i});
    }
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> k;
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != i) k[m++] = tets[t][j];
      std::sort(k.begin(), k.end());
      faces[k].push_back({t, i});
    }
  }
  ASSERT_EQ(mesh->edges().size(), edges.size());
  ASSERT_EQ(mesh->faces().size(), faces.size());
  int id = 0;
  for (const auto& [key, uses] : edges) {
    EXPECT_EQ(mesh->edges()[id], key);
    for (const auto& [t, i] : uses) EXPECT_EQ(mesh->tetEdges()[t][i], id);
    ++id;
  }
  id = 0;
  for (const auto& [key, uses] : faces) {
    EXPECT_EQ(mesh->faces()[id], key);
    ASSERT_LE(uses.size(), 2u);
    const std::array<int, 2> expected = {uses[0].first, uses.size() > 1 ? uses[1].first : -1};
    EXPECT_EQ(mesh->faceTets()[id], expected);
    for (const auto& [t, i] : uses) EXPECT_EQ(mesh->tetFaces()[t][i], id);
    ++id;
  }
  // Incidence: ascending tets of each vertex, every use once.
  std::vector<std::vector<int>> incident(mesh->vertexCount());
  for (int t = 0; t < int(tets.size()); ++t)
    for (int v : tets[t]) incident[v].push_back(t);
  for (std::size_t v = 0; v < incident.size(); ++v) {
    const auto span = mesh->vertexTets(int(v));
    EXPECT_EQ(std::vector<int>(span.begin(), span.end()), incident[v]);
  }
  // Serial sums in index order.
  double volume = 0, length = 0;
  for (const auto& t : tets) {
    const auto& p = mesh->positions();
    volume += signedVolume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
  }
  for (const auto& e : mesh->edges())
    length += (mesh->positions()[e[0]] - mesh->positions()[e[1]]).norm();
  EXPECT_EQ(mesh->totalVolume(), volume);
  EXPECT_NEAR(mesh->totalVolume(), 2.0 * 3.0 * 4.0, 1e-12);
  EXPECT_EQ(mesh->meanEdgeLength(), length / double(mesh->edges().size()));
}

TEST(TetMeshTopology, OneAndTwoThreadsBuildTheSameMesh) {
  const auto build = [](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return shuffledBox(14, 5);  // 14 × 15 × 16 cubes: 20,160 tets, several tasks per pass
  };
  const auto a = build(1), b = build(2);
  EXPECT_EQ(a->edges(), b->edges());
  EXPECT_EQ(a->tetEdges(), b->tetEdges());
  EXPECT_EQ(a->faces(), b->faces());
  EXPECT_EQ(a->faceTets(), b->faceTets());
  EXPECT_EQ(a->tetFaces(), b->tetFaces());
  EXPECT_EQ(a->boundaryFaces(), b->boundaryFaces());
  EXPECT_EQ(a->boundaryVertices(), b->boundaryVertices());
  EXPECT_EQ(a->vertexNormals(), b->vertexNormals());
  EXPECT_EQ(a->tetVolumes(), b->tetVolumes());
  EXPECT_EQ(a->totalVolume(), b->totalVolume());
  EXPECT_EQ(a->meanEdgeLength(), b->meanEdgeLength());
  for (std::size_t v = 0; v < a->vertexCount(); ++v) {
    const auto x = a->vertexTets(int(v)), y = b->vertexTets(int(v));
    ASSERT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
  }
}

TEST(TetMeshTopology, ACancelledBuildThrowsCancelled) {
  const auto box = shuffledBox(6, 2);
  std::atomic<bool> cancel = true;
  const Progress progress({}, &cancel);
  EXPECT_THROW(TetMesh(box->positions(), box->tets(), progress), Cancelled);
  cancel = false;
  const TetMesh mesh(box->positions(), box->tets(), progress);
  EXPECT_EQ(mesh.faces(), box->faces());
}

TEST(TetMeshTopology, InvalidMeshesThrowValidatesWords) {
  // Each problem the fast checks catch must produce validate()'s full report.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}};
  const std::vector<std::vector<TetMesh::Tet>> cases = {
      {},                                          // no tets
      {{0, 1, 2, 3}, {0, 2, 1, 4}},                // vertex 5 unused
      {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}},  // face (0, 1, 2) in three tets
      {{0, 1, 2, 3}, {0, 1, 2, 9}},                // out of range
      {{0, 1, 2, 2}, {0, 2, 1, 4}, {1, 2, 3, 5}},  // repeated vertex
  };
  for (const auto& tets : cases) {
    const auto problems = TetMesh::validate(p, tets);
    ASSERT_FALSE(problems.empty());
    try {
      TetMesh mesh(p, tets);
      ADD_FAILURE() << "no error for " << problems[0];
    } catch (const Error& e) {
      for (const auto& problem : problems)
        EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    }
  }
  p[5] = Vec3(0.5, 0.5, std::nan(""));
  EXPECT_THROW(TetMesh(p, {{0, 1, 2, 3}, {0, 2, 1, 4}, {1, 2, 3, 5}}), Error);
}

/// Every derived array of two meshes bitwise equal.
void expectSameMesh(const TetMesh& a, const TetMesh& b) {
  EXPECT_EQ(a.edges(), b.edges());
  EXPECT_EQ(a.tetEdges(), b.tetEdges());
  EXPECT_EQ(a.faces(), b.faces());
  EXPECT_EQ(a.faceTets(), b.faceTets());
  EXPECT_EQ(a.tetFaces(), b.tetFaces());
  EXPECT_EQ(a.boundaryFaces(), b.boundaryFaces());
  EXPECT_EQ(a.boundaryVertices(), b.boundaryVertices());
  EXPECT_EQ(a.vertexNormals(), b.vertexNormals());
  EXPECT_EQ(a.tetVolumes(), b.tetVolumes());
  EXPECT_EQ(a.totalVolume(), b.totalVolume());
  EXPECT_EQ(a.meanEdgeLength(), b.meanEdgeLength());
  EXPECT_EQ(a.boundsMin(), b.boundsMin());
  EXPECT_EQ(a.boundsMax(), b.boundsMax());
  for (std::size_t v = 0; v < a.vertexCount(); ++v) {
    const auto x = a.vertexTets(int(v)), y = b.vertexTets(int(v));
    ASSERT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
  }
}

TEST(TetMeshRestore, StoredIdsGiveTheBuiltMeshForAnyThreadCount) {
  const auto built = shuffledBox(14, 7);
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const TetMesh restored(built->positions(), built->tets(),
                           {built->tetEdges(), built->tetFaces(), built->faceTets()});
    expectSameMesh(*built, restored);
  }
}

TEST(TetMeshRestore, IdsThatDoNotMatchTheTetsThrow) {
  const auto mesh = shuffledBox(4, 3);
  const auto& tets = mesh->tets();
  const TetMesh::StoredTopology good{mesh->tetEdges(), mesh->tetFaces(), mesh->faceTets()};
  const int edgeCount = int(mesh->edges().size()), faceCount = int(mesh->faces().size());
  using Stored = TetMesh::StoredTopology;
  std::vector<std::pair<std::string, Stored>> cases;
  auto add = [&](const std::string& what, auto&& damage) {
    Stored s = good;
    damage(s);
    cases.push_back({what, std::move(s)});
  };
  add("two edge ids of a tet swapped",
      [](Stored& s) { std::swap(s.tetEdges[5][0], s.tetEdges[5][3]); });
  add("two face ids of a tet swapped",
      [](Stored& s) { std::swap(s.tetFaces[9][1], s.tetFaces[9][2]); });
  add("an edge id out of range", [&](Stored& s) { s.tetEdges[0][2] = edgeCount; });
  add("a face id out of range", [&](Stored& s) { s.tetFaces[3][3] = 4 * int(tets.size()); });
  add("a negative id", [](Stored& s) { s.tetEdges[1][1] = -1; });
  add("the last edge unused", [&](Stored& s) {
    for (auto& ids : s.tetEdges)
      for (int& id : ids)
        if (id == edgeCount - 1) id = 0;
  });
  add("one tet's face id changed",
      [&](Stored& s) { s.tetFaces[2][0] = (s.tetFaces[2][0] + 1) % faceCount; });
  add("a tet missing", [](Stored& s) {
    s.tetEdges.pop_back();
    s.tetFaces.pop_back();
  });
  // Consistent everywhere but not in lexicographic order: only the ascending check finds it.
  add("edges renumbered consistently", [&](Stored& s) {
    for (auto& ids : s.tetEdges)
      for (int& id : ids) id = edgeCount - 1 - id;
  });
  add("faces renumbered consistently", [&](Stored& s) {
    for (auto& ids : s.tetFaces)
      for (int& id : ids) id = (id + 1) % faceCount;
    std::rotate(s.faceTets.rbegin(), s.faceTets.rbegin() + 1, s.faceTets.rend());
  });
  // faceTets: a face's tets swapped, a boundary face given a second tet, an inner face's
  // second tet dropped, a face list too short.
  int inner = 0, boundary = 0;
  while (good.faceTets[inner][1] < 0) ++inner;
  while (good.faceTets[boundary][1] >= 0) ++boundary;
  add("a face's tets in descending order",
      [&](Stored& s) { std::swap(s.faceTets[inner][0], s.faceTets[inner][1]); });
  add("a boundary face with a second tet", [&](Stored& s) {
    s.faceTets[boundary][1] = std::min(s.faceTets[boundary][0] + 1, int(tets.size()) - 1);
  });
  add("an inner face's second tet dropped", [&](Stored& s) { s.faceTets[inner][1] = -1; });
  add("a face list too short", [](Stored& s) { s.faceTets.pop_back(); });
  for (auto& [what, stored] : cases) {
    try {
      TetMesh restored(mesh->positions(), tets, stored);
      ADD_FAILURE() << "restored with " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("stored mesh topology does not match"),
                std::string::npos)
          << what << ": " << e.what();
    }
  }
  // The undamaged ids restore; an invalid mesh still gets validate()'s words, whatever the ids.
  EXPECT_NO_THROW(TetMesh(mesh->positions(), tets, good));
  auto flipped = tets;
  std::swap(flipped[0][0], flipped[0][1]);
  try {
    TetMesh bad(mesh->positions(), flipped, good);
    ADD_FAILURE() << "an inverted tet was restored";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tfd::core
