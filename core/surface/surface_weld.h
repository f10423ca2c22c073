#pragma once
// Welding a triangle soup into a connected surface: files from modelling tools often repeat a
// vertex once per face (UV or normal seams, per-face export), which leaves a geometrically
// closed surface with open edges that TetGen refuses. Exporters that evaluate a parametric
// surface write the two sides of a seam a rounding error apart (cos 2π ≠ 1 in floating point;
// float32 STL), so the copies are close rather than equal: weldCloseVertices() takes those too.
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

/// As weldCoincidentVertices(), then merges each remaining vertex, in order, into the first
/// kept vertex at most `tolerance` away (Euclidean), if any: a kept vertex never moves, so
/// a chain of vertices each within `tolerance` of the next does not collapse into one.
/// tolerance ≤ 0: exact positions only. Cost: O(n) expected (a hash grid of cell `tolerance`).
WeldReport weldCloseVertices(SurfaceMesh& mesh, double tolerance);

/// Triangles on the same three vertices, as welding leaves them where a file repeats a face
/// (a copy facing the same way) or where two solids meet in a shared face written once for
/// each (two copies facing opposite ways, a wall of no thickness inside the union). Each
/// opposite pair is removed, which joins the two solids; of copies facing the same way, the
/// first stays. Returns how many triangles were removed; the others keep their order.
std::size_t removeRepeatedTriangles(SurfaceMesh& mesh);

/// For a surface with open edges (on one triangle only): the weld tolerance that gives every
/// open edge a twin, i.e. the largest, over open edges, of the distance to the nearest other
/// open edge matched end to end (the farther of its two ends; a shared end is 0 away).
/// Infinity when that exceeds `within`, 0 when there is no open edge. For advice: welding at
/// that distance need not close the surface.
double openEdgeWeldDistance(const SurfaceMesh& mesh, double within);

}  // namespace tfd::core
