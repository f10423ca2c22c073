#include "core/edit/region_complex.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace tfd::core {
namespace {

int indexIn(const std::vector<int>& sorted, int value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return it != sorted.end() && *it == value ? static_cast<int>(it - sorted.begin()) : -1;
}

}  // namespace

int RegionComplex::localVertex(int meshVertex) const { return indexIn(vertices, meshVertex); }
int RegionComplex::localEdge(int meshEdge) const { return indexIn(edges, meshEdge); }
int RegionComplex::localTet(int meshTet) const { return indexIn(tets, meshTet); }

int RegionComplex::components() const {
  const int n = static_cast<int>(vertices.size());
  std::vector<char> seen(n, 0);
  std::vector<int> stack;
  int pieces = 0;
  for (int s = 0; s < n; ++s) {
    if (seen[s]) continue;
    ++pieces;
    seen[s] = 1;
    stack.push_back(s);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int k = start[i]; k < start[i + 1]; ++k) {
        if (!seen[neighbour[k]]) {
          seen[neighbour[k]] = 1;
          stack.push_back(neighbour[k]);
        }
      }
    }
  }
  return pieces;
}

RegionComplex regionComplex(const TetMesh& mesh, const std::vector<int>& tets) {
  if (tets.empty()) throw Error("region: no tets");
  RegionComplex r;
  r.tets = tets;
  std::sort(r.tets.begin(), r.tets.end());
  r.tets.erase(std::unique(r.tets.begin(), r.tets.end()), r.tets.end());
  if (r.tets.front() < 0 || r.tets.back() >= static_cast<int>(mesh.tetCount())) {
    throw Error("region: tet id " +
                std::to_string(r.tets.front() < 0 ? r.tets.front() : r.tets.back()) +
                " is not a tet of the mesh (" + std::to_string(mesh.tetCount()) + " tets)");
  }
  r.vertices.reserve(r.tets.size() * 4);
  r.edges.reserve(r.tets.size() * 6);
  for (int t : r.tets) {
    for (int v : mesh.tets()[t]) r.vertices.push_back(v);
    for (int e : mesh.tetEdges()[t]) r.edges.push_back(e);
  }
  std::sort(r.vertices.begin(), r.vertices.end());
  r.vertices.erase(std::unique(r.vertices.begin(), r.vertices.end()), r.vertices.end());
  std::sort(r.edges.begin(), r.edges.end());
  r.edges.erase(std::unique(r.edges.begin(), r.edges.end()), r.edges.end());

  const int n = static_cast<int>(r.vertices.size());
  std::vector<std::array<int, 3>> half;  // (local from, local to, local edge)
  half.reserve(r.edges.size() * 2);
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    const auto& ends = mesh.edges()[r.edges[e]];
    const int a = r.localVertex(ends[0]), b = r.localVertex(ends[1]);
    half.push_back({a, b, static_cast<int>(e)});
    half.push_back({b, a, static_cast<int>(e)});
  }
  std::sort(half.begin(), half.end());
  r.start.assign(n + 1, 0);
  r.neighbour.reserve(half.size());
  r.neighbourEdge.reserve(half.size());
  for (const auto& h : half) {
    ++r.start[h[0] + 1];
    r.neighbour.push_back(h[1]);
    r.neighbourEdge.push_back(h[2]);
  }
  for (int i = 0; i < n; ++i) r.start[i + 1] += r.start[i];
  return r;
}

int regionEdge(const RegionComplex& region, int localA, int localB) {
  const auto begin = region.neighbour.begin() + region.start[localA];
  const auto end = region.neighbour.begin() + region.start[localA + 1];
  const auto it = std::lower_bound(begin, end, localB);
  return it != end && *it == localB ? region.neighbourEdge[it - region.neighbour.begin()] : -1;
}

}  // namespace tfd::core
