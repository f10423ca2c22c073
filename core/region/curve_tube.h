#pragma once
// The mesh vertices inside a tube around a polyline (paper §5, "Parameterization": "we compute
// a tubular neighborhood for the specified curve (cylinder if open curve and torus if a loop)").
//
// Inputs: a mesh, a polyline (open or closed) and a radius r > 0.
// Output: every vertex v with Euclidean distance d(v) ≤ r to the polyline that is connected to
// the curve through mesh edges whose both ends are within the tube, with its closest polyline
// point (segment and parameter) and d(v); sorted by vertex id.
//
// Distance choice. The distance is the exact distance to the polyline, clipped to the part of
// the tube reachable inside the volume: a breadth-first search seeded at the vertices of the
// tets the curve passes through, which crosses only mesh edges (so only through the volume)
// and only into vertices within r. Inside a locally convex part of the volume this is the true
// inside-the-volume distance; across a thin gap or slot of a non-convex volume the far side,
// not connected through the tube, is excluded. Graph (Dijkstra) distances on mesh edges would
// overestimate the distance by up to ~20 % and make the tube jagged; fast marching would cost
// more for no difference at tube scale. The exact closest point is also what the local
// linearisation needs (the displacement v − closest point).
//
// Cost: O(tube size × vertex valence) plus the curve length over the edge length for the seeds;
// vertices far from the curve are never visited (the segments are bucketed in a uniform grid of
// cell size r, so each distance query only looks at segments within reach).
// Deterministic (sequential; results sorted by vertex id).
#include <span>
#include <vector>

#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

struct TubeVertex {
  int vertex = -1;
  int segment = -1;     ///< polyline segment holding the closest point (closed: n − 1 closes it)
  double t = 0;         ///< closest point = (1 − t)·P[segment] + t·P[segment + 1]
  double distance = 0;  ///< Euclidean distance from the vertex to the polyline
};

struct TubeQuery {
  std::vector<TubeVertex> vertices;  ///< ascending vertex id
  /// Polyline points outside the mesh (their index), ascending; callers decide if that is an
  /// error.
  std::vector<int> pointsOutside;
};

/// Throws core::Error when the polyline has fewer than two points (three when closed), a
/// non-finite point, or radius is not a finite positive number.
TubeQuery findTubeVertices(const TetMesh& mesh, std::span<const Vec3> polyline, bool closed,
                           double radius);

/// Closest point of segment [a, b] to p as the parameter t ∈ [0, 1].
double closestSegmentParameter(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace tfd::core
