#include "core/edit/angle_defects.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>

#include "core/design/parallel_transport.h"
#include "core/edit/reference_field.h"
#include "core/error.h"

namespace tfd::core {
namespace {

double wrapHalfTurn(double x) { return x - std::numbers::pi * std::round(x / std::numbers::pi); }

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

int lineFieldIndex(const std::array<Vec3, 3>& n, const std::array<Vec3, 3>& m) {
  double turn = sphericalTriangleArea(n[0], n[1], n[2]);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    turn += wrapHalfTurn(signedAngle(transportRotation(n[i], n[j]) * m[i], m[j], n[j]));
  }
  return static_cast<int>(std::lround(turn / std::numbers::pi));
}

AngleDefects angleDefects(const TensorField& field, const RegionComplex& region,
                          const VectorisedEigenvector& n, const std::vector<char>& held,
                          std::span<const int> targetTets) {
  const TetMesh& mesh = field.mesh();
  if (n.vertices != region.vertices || held.size() != mesh.vertexCount())
    throw Error("angle defects: directions or held flags do not match the region");
  // The given field's medium eigenvector: from the vectorisation's decompositions when it
  // kept them (the same decompositions), otherwise decomposed here.
  const bool decomposed = n.eigen.size() == region.vertices.size();
  auto index = [&](const TetMesh::Face& f) {
    std::array<Vec3, 3> nf, mf;
    for (int i = 0; i < 3; ++i) {
      const int local = region.localVertex(f[i]);
      nf[i] = n.directions[local];
      mf[i] = decomposed ? n.eigen[local].medium
                         : Vec3(eigenDecompose(field.at(f[i]).deviator()).vectors.col(1));
    }
    try {
      return lineFieldIndex(nf, mf);
    } catch (const Error&) {
      return 1;  // opposite directions: no transport, no lift either
    }
  };
  // Each face once, from the lower of its region tets, in tet order: chunks of tets in
  // parallel, their findings concatenated in chunk order.
  constexpr std::size_t kChunk = 8192;
  const std::size_t chunks = (region.tets.size() + kChunk - 1) / kChunk;
  struct Found {
    std::vector<std::pair<int, int>> surface;  // (face, index)
    std::vector<int> heldFaces;                // held triangles with a non-zero index
  };
  std::vector<Found> found(chunks);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    Found& out = found[c];
    const std::size_t end = std::min(region.tets.size(), (c + 1) * kChunk);
    for (std::size_t k = c * kChunk; k < end; ++k) {
      const int t = region.tets[k];
      for (int f : mesh.tetFaces()[t]) {
        const auto& ft = mesh.faceTets()[f];
        const int other = ft[0] == t ? ft[1] : ft[0];
        if (other >= 0 && other < t && region.localTet(other) >= 0) continue;  // seen from other
        const TetMesh::Face& v = mesh.faces()[f];
        const bool heldTriangle = held[v[0]] && held[v[1]] && held[v[2]];
        if (other < 0) {
          const int i = index(mesh.orientedBoundaryFace(f));
          out.surface.emplace_back(f, i);
          if (heldTriangle && i != 0) out.heldFaces.push_back(f);
        } else if (heldTriangle && index(v) != 0) {
          out.heldFaces.push_back(f);
        }
      }
    }
  });
  AngleDefects out;
  std::vector<std::pair<int, int>> surface;  // (face, index)
  for (const Found& f : found) {
    surface.insert(surface.end(), f.surface.begin(), f.surface.end());
    out.faces.insert(out.faces.end(), f.heldFaces.begin(), f.heldFaces.end());
    out.heldTriangles += static_cast<int>(f.heldFaces.size());
  }
  // Surface patches: the surface faces joined through shared edges.
  std::vector<std::tuple<int, int, int>> edges;  // (lower vertex, higher vertex, surface slot)
  for (int s = 0; s < static_cast<int>(surface.size()); ++s) {
    const TetMesh::Face& v = mesh.faces()[surface[s].first];
    for (int i = 0; i < 3; ++i)
      edges.emplace_back(std::min(v[i], v[(i + 1) % 3]), std::max(v[i], v[(i + 1) % 3]), s);
  }
  std::sort(edges.begin(), edges.end());
  std::vector<int> parent(surface.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 1; i < edges.size(); ++i) {
    if (std::get<0>(edges[i]) != std::get<0>(edges[i - 1]) ||
        std::get<1>(edges[i]) != std::get<1>(edges[i - 1]))
      continue;
    const int a = findRoot(parent, std::get<2>(edges[i])),
              b = findRoot(parent, std::get<2>(edges[i - 1]));
    parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> total(surface.size(), 0);
  for (int s = 0; s < static_cast<int>(surface.size()); ++s)
    total[findRoot(parent, s)] += surface[s].second;
  for (int s = 0; s < static_cast<int>(surface.size()); ++s)
    out.unbalancedPatches += parent[s] == s && total[s] != 0;
  for (int s = 0; s < static_cast<int>(surface.size()); ++s) {
    const auto [f, k] = surface[s];
    if (k == 0 || total[findRoot(parent, s)] == 0) continue;
    if (std::binary_search(targetTets.begin(), targetTets.end(), mesh.faceTets()[f][0])) continue;
    out.faces.push_back(f);
  }
  std::sort(out.faces.begin(), out.faces.end());
  out.faces.erase(std::unique(out.faces.begin(), out.faces.end()), out.faces.end());
  return out;
}

}  // namespace tfd::core
