#include "core/region/ball_check.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace tfd::core {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
  int roots() {
    int n = 0;
    for (std::size_t i = 0; i < parent.size(); ++i) n += find(int(i)) == int(i);
    return n;
  }
};

std::uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

/// Pieces of the tets connected through faces: a breadth-first flood from each tet not yet
/// reached (`index` maps a mesh tet to its position in `tets`, −1 outside).
int tetComponents(const TetMesh& mesh, const std::vector<int>& tets,
                  const std::vector<int>& index) {
  std::vector<char> reached(tets.size(), 0);
  std::vector<int> queue;
  queue.reserve(tets.size());
  int pieces = 0;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    if (reached[i] || index[tets[i]] != int(i)) continue;  // reached, or a repeat
    ++pieces;
    reached[i] = 1;
    queue.assign(1, int(i));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int t = tets[queue[head]];
      for (int f : mesh.tetFaces()[t]) {
        const auto& ft = mesh.faceTets()[f];
        const int other = ft[0] == t ? ft[1] : ft[0];
        if (other < 0) continue;
        const int j = index[other];
        if (j >= 0 && !reached[j]) reached[j] = 1, queue.push_back(j);
      }
    }
  }
  return pieces;
}

}  // namespace

BallCheck checkTopologicalBall(const TetMesh& mesh, std::span<const int> tetSpan) {
  BallCheck r;
  std::vector<int> tets(tetSpan.begin(), tetSpan.end());
  if (!std::is_sorted(tets.begin(), tets.end()))  // regions usually arrive ascending
    std::sort(tets.begin(), tets.end());
  if (tets.empty()) {
    r.problem = "the region is empty";
    return r;
  }
  // Position of each member in `tets` (the first of repeats), −1 for the other mesh tets: one
  // int per mesh tet, faster than a hash map for the large regions of a 1M-tet mesh.
  std::vector<int> index(mesh.tetCount(), -1);
  for (std::size_t i = 0; i < tets.size(); ++i)
    if (index[tets[i]] < 0) index[tets[i]] = int(i);
  // The boundary analysis runs beside the face-connected pieces (a flood through the region):
  // independent, each deterministic.
  int badEdges = 0, pinched = 0;
  const auto boundary = [&] {
    // Boundary faces (oriented or not does not matter for the counts).
    std::vector<int> faces;
    for (int t : tets) {
      for (int f : mesh.tetFaces()[t]) {
        const auto& ft = mesh.faceTets()[f];
        const int other = ft[0] == t ? ft[1] : ft[0];
        if (other >= 0 && index[other] >= 0) continue;
        faces.push_back(f);
        r.surfaceFaces += other < 0;
      }
    }
    r.boundaryFaces = int(faces.size());
    // Edges and vertices of the boundary faces as sorted (key, face) lists: each run of equal
    // keys is the faces around one edge or vertex (cheaper than hash maps of lists).
    std::vector<std::pair<std::uint64_t, int>> edgeFaces;  // edge -> boundary faces
    std::vector<std::pair<int, int>> vertexFaces;          // vertex -> boundary faces
    edgeFaces.reserve(3 * faces.size());
    vertexFaces.reserve(3 * faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const auto& f = mesh.faces()[faces[i]];
      for (int k = 0; k < 3; ++k) {
        edgeFaces.emplace_back(edgeKey(f[k], f[(k + 1) % 3]), int(i));
        vertexFaces.emplace_back(f[k], int(i));
      }
    }
    std::sort(edgeFaces.begin(), edgeFaces.end());
    std::sort(vertexFaces.begin(), vertexFaces.end());
    int edgeCount = 0;
    UnionFind surface(faces.size());
    for (std::size_t i = 0, j; i < edgeFaces.size(); i = j) {
      for (j = i + 1; j < edgeFaces.size() && edgeFaces[j].first == edgeFaces[i].first; ++j)
        surface.join(edgeFaces[i].second, edgeFaces[j].second);
      ++edgeCount;
      badEdges += j - i != 2;
    }
    r.boundaryComponents = faces.empty() ? 0 : surface.roots();

    // Pinched vertices: the faces around a vertex must form one fan (connected through edges
    // at that vertex).
    int vertexCount = 0;
    std::vector<std::pair<int, int>> spokes;  // (other vertex of an edge at v, fan index)
    for (std::size_t i = 0, j; i < vertexFaces.size(); i = j) {
      const int v = vertexFaces[i].first;
      for (j = i + 1; j < vertexFaces.size() && vertexFaces[j].first == v; ++j) {
      }
      ++vertexCount;
      spokes.clear();
      for (std::size_t k = i; k < j; ++k)
        for (int w : mesh.faces()[faces[vertexFaces[k].second]])
          if (w != v) spokes.emplace_back(w, int(k - i));
      std::sort(spokes.begin(), spokes.end());
      UnionFind fan(j - i);
      for (std::size_t k = 1; k < spokes.size(); ++k)
        if (spokes[k].first == spokes[k - 1].first)
          fan.join(spokes[k].second, spokes[k - 1].second);
      pinched += fan.roots() != 1;
    }
    r.eulerCharacteristic = vertexCount - edgeCount + int(faces.size());
  };
  tbb::parallel_invoke([&] { r.components = tetComponents(mesh, tets, index); }, boundary);

  if (r.components != 1) {
    r.problem = "the tets form " + std::to_string(r.components) + " separate pieces";
  } else if (badEdges > 0) {
    r.problem = std::to_string(badEdges) + " boundary edges are not on exactly two boundary faces";
  } else if (pinched > 0) {
    r.problem = std::to_string(pinched) + " boundary vertices are pinched";
  } else if (r.boundaryComponents != 1) {
    r.problem =
        "the boundary has " + std::to_string(r.boundaryComponents) + " components (a cavity)";
  } else if (r.eulerCharacteristic != 2) {
    r.problem = "the boundary has Euler characteristic " + std::to_string(r.eulerCharacteristic) +
                " (a sphere has 2: the region has a handle or tunnel)";
  } else {
    r.ball = true;
  }
  return r;
}

}  // namespace tfd::core
