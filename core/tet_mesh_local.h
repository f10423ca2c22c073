#pragma once
// Local numbering inside a tet, shared by core/tet_mesh.cpp and core/tet_mesh_topology.cpp.
#include <cmath>

#include "core/tet_mesh.h"

namespace tfd::core::tet_local {

/// Local vertex pairs of the six edges, in TetMesh::tetEdges() order.
inline constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
/// Local vertex triples of the four faces: the face opposite vertex i leaves out i.
inline constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

/// Signed volume of tet t and whether it passes validate()'s test (volume above 1e-14 times
/// the cube of the longest edge, so the check is scale-free).
inline bool volumeOk(const std::vector<Vec3>& positions, const TetMesh::Tet& tet, double& volume) {
  volume = signedVolume(positions[tet[0]], positions[tet[1]], positions[tet[2]], positions[tet[3]]);
  // One square root of the largest squared length: sqrt is monotone and correctly rounded,
  // so this is bitwise the largest length.
  double longest2 = 0;
  for (const auto& e : kEdge)
    longest2 = std::max(longest2, (positions[tet[e[0]]] - positions[tet[e[1]]]).squaredNorm());
  const double longest = std::sqrt(longest2);
  return volume > 1e-14 * longest * longest * longest;
}

}  // namespace tfd::core::tet_local
