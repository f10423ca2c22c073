#pragma once
// Welding a triangle soup into a connected surface: files from modelling tools often repeat a
// vertex once per face (UV or normal seams, per-face export), which leaves a geometrically
// closed surface with open edges that TetGen refuses.
#include <cstddef>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

struct WeldReport {
  std::size_t mergedVertices = 0;    ///< vertices replaced by an earlier one at the same place
  std::size_t droppedTriangles = 0;  ///< triangles that became degenerate (two equal corners)
};

/// Merges vertices with exactly equal positions (−0 equals +0), keeping the first of each in
/// order, and drops triangles that lose a corner. Vertex ids stay in order of first appearance,
/// so a mesh without duplicates comes back unchanged.
WeldReport weldCoincidentVertices(SurfaceMesh& mesh);

}  // namespace tfd::core
