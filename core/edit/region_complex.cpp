#include "core/edit/region_complex.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
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
  if (std::is_sorted(ids.begin(), ids.end()) &&
      std::adjacent_find(ids.begin(), ids.end()) == ids.end()) {  // the usual region tets
    for (std::size_t i = 0; i < ids.size(); ++i) table[ids[i]] = static_cast<int>(i);
    return ids;
  }
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

/// Ascending ids of the corners (K = 4, `items` = tets()) or edges (K = 6, tetEdges()) of the
/// region's tets, and their local index in `table` (size count, −1 elsewhere): flagged in
/// parallel, numbered by one scan.
template <std::size_t K>
std::vector<int> itemsOfTets(const std::vector<int>& tets,
                             const std::vector<std::array<int, K>>& items, std::size_t count,
                             std::vector<int>& table) {
  table.assign(count, -1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tets.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        for (int id : items[tets[i]])
                          std::atomic_ref<int>(table[id]).store(0, std::memory_order_relaxed);
                    });
  std::vector<int> out;
  for (std::size_t id = 0; id < count; ++id)
    if (table[id] == 0) table[id] = static_cast<int>(out.size()), out.push_back(int(id));
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
  r.vertices = itemsOfTets(r.tets, mesh.tets(), mesh.vertexCount(), r.vertexLocal);
  r.edges = itemsOfTets(r.tets, mesh.tetEdges(), mesh.edges().size(), r.edgeLocal);

  // CSR adjacency: count, place (in any order), then sort each vertex's (neighbour, edge)
  // pairs, which makes the result the same for any thread count.
  const int n = static_cast<int>(r.vertices.size());
  const int edgeCount = static_cast<int>(r.edges.size());
  r.start.assign(n + 1, 0);
  auto forEdges = [&](auto&& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, edgeCount, 4096),
                      [&](const tbb::blocked_range<int>& b) {
                        for (int e = b.begin(); e != b.end(); ++e) {
                          const auto& ends = mesh.edges()[r.edges[e]];
                          body(e, r.vertexLocal[ends[0]], r.vertexLocal[ends[1]]);
                        }
                      });
  };
  forEdges([&](int, int a, int b) {
    std::atomic_ref<int>(r.start[a + 1]).fetch_add(1, std::memory_order_relaxed);
    std::atomic_ref<int>(r.start[b + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  for (int i = 0; i < n; ++i) r.start[i + 1] += r.start[i];
  std::vector<std::pair<int, int>> half(r.start[n]);
  std::vector<int> fill(r.start.begin(), r.start.end() - 1);
  forEdges([&](int e, int a, int b) {
    half[std::atomic_ref<int>(fill[a]).fetch_add(1, std::memory_order_relaxed)] = {b, e};
    half[std::atomic_ref<int>(fill[b]).fetch_add(1, std::memory_order_relaxed)] = {a, e};
  });
  r.neighbour.resize(half.size());
  r.neighbourEdge.resize(half.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 1024), [&](const tbb::blocked_range<int>& b) {
    for (int i = b.begin(); i != b.end(); ++i) {
      std::sort(half.begin() + r.start[i], half.begin() + r.start[i + 1]);
      for (int k = r.start[i]; k < r.start[i + 1]; ++k) {
        r.neighbour[k] = half[k].first;
        r.neighbourEdge[k] = half[k].second;
      }
    }
  });
  return r;
}

int regionEdge(const RegionComplex& region, int localA, int localB) {
  const auto begin = region.neighbour.begin() + region.start[localA];
  const auto end = region.neighbour.begin() + region.start[localA + 1];
  const auto it = std::lower_bound(begin, end, localB);
  return it != end && *it == localB ? region.neighbourEdge[it - region.neighbour.begin()] : -1;
}

}  // namespace tfd::core
