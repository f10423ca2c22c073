#include "core/region/region_vertices.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace tfd::core {

std::vector<unsigned char> tetFlags(const TetMesh& mesh, std::span<const int> tets) {
  std::vector<unsigned char> in(mesh.tetCount(), 0);
  for (int t : tets) in[t] = 1;
  return in;
}

RegionVertices regionVertices(const TetMesh& mesh, std::span<const int> tets) {
  const std::vector<unsigned char> in = tetFlags(mesh, tets);
  RegionVertices r;
  r.held.assign(mesh.vertexCount(), 0);
  // Ascending unique vertices by flags (one byte per mesh vertex) rather than by sorting the
  // four corners of every tet: the region of a 1M-tet edit has 2M corners. The passes over the
  // tets and the vertices run in parallel (flags and integer counts: the same for any split),
  // so this reader of a region shares the cores with the others (region_examination.h).
  std::vector<unsigned char> used(mesh.vertexCount(), 0);
  constexpr std::size_t kGrain = 4096;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tets.size(), kGrain), [&](const auto& b) {
    for (std::size_t i = b.begin(); i != b.end(); ++i)
      for (int v : mesh.tets()[tets[i]])
        std::atomic_ref<unsigned char>(used[v]).store(1, std::memory_order_relaxed);
  });
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) r.vertices.push_back(int(v));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, r.vertices.size(), kGrain),
                    [&](const auto& b) {
                      for (std::size_t i = b.begin(); i != b.end(); ++i) {
                        const int v = r.vertices[i];
                        bool outside = false;
                        for (int t : mesh.vertexTets(v)) outside = outside || !in[t];
                        r.held[v] = outside;
                      }
                    });
  for (int v : r.vertices) {
    if (r.held[v]) continue;
    r.free.push_back(v);
    r.freeOnSurface += mesh.isBoundaryVertex(v);
  }
  using Counts = std::pair<std::size_t, std::size_t>;  // (surface faces, held faces)
  const Counts faces = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, tets.size(), kGrain), Counts{0, 0},
      [&](const auto& b, Counts c) {
        for (std::size_t i = b.begin(); i != b.end(); ++i) {
          const int t = tets[i];
          for (int f : mesh.tetFaces()[t]) {
            const auto& ft = mesh.faceTets()[f];
            const int other = ft[0] == t ? ft[1] : ft[0];
            if (other < 0)
              ++c.first;
            else if (!in[other])
              ++c.second;
          }
        }
        return c;
      },
      [](Counts a, const Counts& b) {
        return Counts{a.first + b.first, a.second + b.second};
      });
  r.surfaceFaces = faces.first;
  r.heldFaces = faces.second;
  return r;
}

}  // namespace tfd::core
