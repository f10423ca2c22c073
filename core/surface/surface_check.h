#pragma once
// Checks and measures of closed triangle surfaces (what a solid mesher needs from its input).
#include <string>
#include <vector>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

/// Problems that stop `mesh` from bounding a solid, each one a sentence naming the triangle,
/// edge or vertex: no triangles, a vertex index out of range, a triangle repeating a vertex, a
/// non-finite coordinate, an open edge (one triangle), a non-manifold edge (more than two), an
/// edge whose two triangles run it in the same direction (inconsistent orientation), a
/// non-manifold vertex (its triangles form more than one fan), a zero enclosed volume.
/// Unreferenced vertices are allowed. Empty when the surface is closed, manifold and
/// consistently oriented. At most `maxReported` problems of each kind are spelled out.
std::vector<std::string> closedSurfaceProblems(const SurfaceMesh& mesh, int maxReported = 5);

/// Signed volume enclosed by a closed, consistently oriented surface (divergence theorem, sum
/// of signed tets from the origin): positive when the triangles are counter-clockwise seen
/// from outside. Summed in triangle order, so the result is reproducible.
double enclosedVolume(const SurfaceMesh& mesh);

/// Total triangle area.
double surfaceArea(const SurfaceMesh& mesh);

/// Mean length of the unique edges.
double meanEdgeLength(const SurfaceMesh& mesh);

/// Lower median length of the triangles' sides (an edge of two triangles counts twice; 0 for
/// none): a scale that a few outlying vertices or slivers do not move.
double medianEdgeLength(const SurfaceMesh& mesh);

/// Euler characteristic V − E + F counting only referenced vertices (2 − 2·genus per closed
/// connected component).
long eulerCharacteristic(const SurfaceMesh& mesh);

/// Number of connected components (triangles sharing a vertex are connected); vertices no
/// triangle uses are not counted.
int connectedComponents(const SurfaceMesh& mesh);

/// The connected component of each vertex (triangles sharing a vertex are connected),
/// numbered 0, 1, ... in the order of their first triangle; −1 for a vertex no triangle uses.
std::vector<int> vertexPieces(const SurfaceMesh& mesh);

/// Removes vertices no triangle references, keeping the order of the others.
void removeUnreferencedVertices(SurfaceMesh& mesh);

/// Reverses every triangle (inside out).
void flipOrientation(SurfaceMesh& mesh);

}  // namespace tfd::core
