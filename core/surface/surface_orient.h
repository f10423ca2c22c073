#pragma once
// Making the triangles of a closed surface agree in orientation: meshes from scans, CAD
// exports and public model collections often have a few triangles wound the wrong way, which
// leaves the surface closed and manifold but not the boundary of a solid as written.
#include <cstddef>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

struct OrientReport {
  std::size_t flippedTriangles = 0;
  /// false: nothing changed, because not every edge is on exactly two triangles, or because
  /// a piece is one-sided (then `oneSided`: a Klein bottle, a projective plane)
  bool applied = false;
  bool oneSided = false;
};

/// When every edge lies on exactly two triangles, reverses the triangles that run a shared edge
/// in the same direction as their neighbour, piece by piece (triangles connected through
/// edges), keeping in each piece the orientation most of its triangles already have (ties:
/// that of its first triangle). Otherwise, or when a piece cannot be oriented, leaves the mesh
/// as it is. Deterministic; O(n log n).
OrientReport orientConsistently(SurfaceMesh& mesh);

}  // namespace tfd::core
