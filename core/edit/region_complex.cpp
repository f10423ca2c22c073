#include "core/edit/region_complex.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/error.h"

namespace tfd::core {
namespace {

/// Ascending unique ids of `ids` (each < `count`), their local index in `table` (size count,
/// −1 elsewhere). A flag per id instead of sorting the repeats: only the unique ids are sorted.
std::vector<int> uniqueAscending(const std::vector<int>& ids, std::size_t count,
                                 std::vector<int>& table) {
  table.assign(count, -1);
  std::vector<int> out;
  out.reserve(ids.size() / 4 + 16);
  for (int id : ids) {
    if (table[id] == -1) {
      table[id] = 0;
      out.push_back(id);
    }
  }
  std::sort(out.begin(), out.end());
  for (std::size_t i = 0; i < out.size(); ++i) table[out[i]] = static_cast<int>(i);
  return out;
}

}  // namespace

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
  for (int t : tets) {
    if (t < 0 || t >= static_cast<int>(mesh.tetCount())) {
      throw Error("region: tet id " + std::to_string(t) + " is not a tet of the mesh (" +
                  std::to_string(mesh.tetCount()) + " tets)");
    }
  }
  RegionComplex r;
  r.tets = uniqueAscending(tets, mesh.tetCount(), r.tetLocal);
  std::vector<int> all;
  all.reserve(r.tets.size() * 6);
  for (int t : r.tets)
    for (int v : mesh.tets()[t]) all.push_back(v);
  r.vertices = uniqueAscending(all, mesh.vertexCount(), r.vertexLocal);
  all.clear();
  for (int t : r.tets)
    for (int e : mesh.tetEdges()[t]) all.push_back(e);
  r.edges = uniqueAscending(all, mesh.edges().size(), r.edgeLocal);

  // CSR adjacency: count, place, then sort each vertex's (neighbour, edge) pairs.
  const int n = static_cast<int>(r.vertices.size());
  r.start.assign(n + 1, 0);
  for (int meshEdge : r.edges) {
    const auto& ends = mesh.edges()[meshEdge];
    ++r.start[r.vertexLocal[ends[0]] + 1];
    ++r.start[r.vertexLocal[ends[1]] + 1];
  }
  for (int i = 0; i < n; ++i) r.start[i + 1] += r.start[i];
  std::vector<std::pair<int, int>> half(r.start[n]);
  std::vector<int> fill(r.start.begin(), r.start.end() - 1);
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    const auto& ends = mesh.edges()[r.edges[e]];
    const int a = r.vertexLocal[ends[0]], b = r.vertexLocal[ends[1]];
    half[fill[a]++] = {b, static_cast<int>(e)};
    half[fill[b]++] = {a, static_cast<int>(e)};
  }
  r.neighbour.resize(half.size());
  r.neighbourEdge.resize(half.size());
  for (int i = 0; i < n; ++i) {
    std::sort(half.begin() + r.start[i], half.begin() + r.start[i + 1]);
    for (int k = r.start[i]; k < r.start[i + 1]; ++k) {
      r.neighbour[k] = half[k].first;
      r.neighbourEdge[k] = half[k].second;
    }
  }
  return r;
}

int regionEdge(const RegionComplex& region, int localA, int localB) {
  const auto begin = region.neighbour.begin() + region.start[localA];
  const auto end = region.neighbour.begin() + region.start[localA + 1];
  const auto it = std::lower_bound(begin, end, localB);
  return it != end && *it == localB ? region.neighbourEdge[it - region.neighbour.begin()] : -1;
}

}  // namespace tfd::core
