#include "core/edit/boundary_flow.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/region/region_vertices.h"

namespace tfd::core {

std::string BoundaryFlow::summary() const {
  const double total = incomingArea + outgoingArea;
  const int percent = total > 0 ? int(std::lround(100 * incomingArea / total)) : 0;
  return "boundary flow of the non-repeating eigenvector: " + std::to_string(incomingFaces) +
         " faces incoming (" + std::to_string(percent) + " % of the area), " +
         std::to_string(outgoingFaces) + " outgoing";
}

BoundaryFlow boundaryFlow(const TetMesh& mesh, std::span<const int> regionTets,
                          const VectorisedEigenvector& vec) {
  const std::vector<unsigned char> in = tetFlags(mesh, regionTets);
  const auto direction = [&](int v) -> Vec3 {
    const auto it = std::lower_bound(vec.vertices.begin(), vec.vertices.end(), v);
    if (it == vec.vertices.end() || *it != v)
      throw Error("boundary flow: vertex " + std::to_string(v) + " has no direction");
    return vec.directions[it - vec.vertices.begin()];
  };
  BoundaryFlow r;
  const auto& p = mesh.positions();
  for (int t : regionTets) {
    for (int i = 0; i < 4; ++i) {
      const int f = mesh.tetFaces()[t][i];
      const auto& ft = mesh.faceTets()[f];
      const int other = ft[0] == t ? ft[1] : ft[0];
      if (other >= 0 && in[other]) continue;
      const auto& fv = mesh.faces()[f];
      Vec3 n = (p[fv[1]] - p[fv[0]]).cross(p[fv[2]] - p[fv[0]]);
      // Outward: away from the tet's vertex opposite the face.
      if (n.dot(p[fv[0]] - p[mesh.tets()[t][i]]) < 0) n = -n;
      const double area = 0.5 * n.norm();
      const Vec3 d = direction(fv[0]) + direction(fv[1]) + direction(fv[2]);
      if (d.dot(n) < 0)
        ++r.incomingFaces, r.incomingArea += area;
      else
        ++r.outgoingFaces, r.outgoingArea += area;
    }
  }
  return r;
}

}  // namespace tfd::core
