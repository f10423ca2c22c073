#include "core/edit/boundary_flow.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "core/linalg/parallel.h"
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
  // Per region tet in parallel (fixed chunks summed in order: the same totals for any thread
  // count); the counts are exact in doubles.
  const auto& p = mesh.positions();
  const auto sums = linalg::deterministicSums<4>(
      regionTets.size(), [&](std::size_t b, std::size_t e, std::array<double, 4>& sum) {
        for (std::size_t k = b; k < e; ++k) {
          const int t = regionTets[k];
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
            const int slot = d.dot(n) < 0 ? 0 : 1;  // incoming, outgoing; their areas + 2
            sum[slot] += 1, sum[slot + 2] += area;
          }
        }
      });
  BoundaryFlow r;
  r.incomingFaces = static_cast<std::size_t>(sums[0]);
  r.outgoingFaces = static_cast<std::size_t>(sums[1]);
  r.incomingArea = sums[2], r.outgoingArea = sums[3];
  return r;
}

}  // namespace tfd::core
