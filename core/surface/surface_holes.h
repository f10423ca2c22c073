#pragma once
// Holes of a nearly closed surface (scans such as the Stanford bunny have a few where the
// scanner saw nothing): loops of open edges, and closing them with a fan of triangles.
#include <cstddef>
#include <vector>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

/// The holes: loops of open edges (edges on one triangle), each listed in the direction a
/// filling triangle runs them (opposite to the triangle beside it), from its smallest vertex.
/// Empty when there is no open edge, or when a vertex starts two open edges (a boundary that
/// touches itself: no unique loops).
std::vector<std::vector<int>> holeLoops(const SurfaceMesh& mesh);

struct HoleFilling {
  std::size_t filled = 0;     ///< holes closed
  std::size_t skipped = 0;    ///< holes longer than asked for, left open
  std::size_t largest = 0;    ///< edges of the longest hole (filled or not)
  std::size_t triangles = 0;  ///< triangles added
};

/// Closes each hole of at most `maxEdges` edges: a hole of 3 edges with one triangle, a longer
/// one with a fan around a new vertex at the mean of its corners, oriented like the triangles
/// around it. Nothing changes when holeLoops() finds no loops.
HoleFilling fillHoles(SurfaceMesh& mesh, std::size_t maxEdges);

}  // namespace tfd::core
