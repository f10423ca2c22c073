#include "core/region/region_vertices.h"

#include <algorithm>

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
  // four corners of every tet: the region of a 1M-tet edit has 2M corners.
  std::vector<unsigned char> used(mesh.vertexCount(), 0);
  for (int t : tets)
    for (int v : mesh.tets()[t]) used[v] = 1;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) r.vertices.push_back(int(v));
  for (int v : r.vertices) {
    bool outside = false;
    for (int t : mesh.vertexTets(v)) outside = outside || !in[t];
    r.held[v] = outside;
    if (!outside) {
      r.free.push_back(v);
      r.freeOnSurface += mesh.isBoundaryVertex(v);
    }
  }
  for (int t : tets) {
    for (int f : mesh.tetFaces()[t]) {
      const auto& ft = mesh.faceTets()[f];
      const int other = ft[0] == t ? ft[1] : ft[0];
      if (other < 0)
        ++r.surfaceFaces;
      else if (!in[other])
        ++r.heldFaces;
    }
  }
  return r;
}

}  // namespace tfd::core
