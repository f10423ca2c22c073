#pragma once
// The insulating sheet of a degenerate curve reconnection (paper §6.2, step 3): one path per
// pair of endpoints joined after the reconnection, the nearest-path partition of the region's
// vertices, and the thickened sheet: the region tets holding an edge whose two vertices have
// different nearest paths. The sheet separates the region into two parts, each holding one
// pair of endpoints.
//
// Distance choice: exact shortest paths in the graph of the region's edges (Dijkstra, edge
// weight = Euclidean length), not fast marching. The paths only serve to label vertices by the
// nearer path, and the label boundary (the sheet) is at least one tet thick; the graph
// distance overestimates Euclidean distance by a similar factor for both paths, so the
// partition differs from the exact Euclidean one only at near-ties. Measured on the six
// reconnection scenarios of tests/core/edit/reconnect_curves_test.cpp (jittered box, 18 cells
// a side): the graph labels agree with the exact Euclidean nearest-path labels on 92–96 % of
// the region's vertices, and 80–87 % of the others are vertices of the sheet's tets anyway
// (the sheet moves by about one tet where they differ). Fast marching would approximate the
// Euclidean labels more closely at a higher cost, for a sheet whose exact place does not
// matter (only that it separates the pairs, which the verification checks).
// Dijkstra costs O(region · log) and stays inside the region by construction (a non-convex
// region never lets a path or a label leak across a gap).
//
// Intersections: when the second path comes within one edge of the first (shares a vertex or
// an edge), it is recomputed avoiding the first path's vertices and their neighbours (the
// paper's "local adjustment"); when no such path exists the sheet fails.
#include <array>
#include <string>
#include <vector>

#include "core/edit/region_complex.h"
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

/// One end of a path: a point on the region's boundary and its source (the path starts at the
/// source's vertices).
struct SheetEnd {
  Vec3 position = Vec3::Zero();
  PointSource source;
};

struct ReconnectSheet {
  std::array<std::vector<int>, 2> paths;  ///< mesh vertex ids, from the first end to the second
  std::array<double, 2> pathLengths{0, 0};
  bool adjusted = false;  ///< the second path was rerouted around the first
  int contacts = 0;       ///< vertices of the second path on or next to the first, before that
  std::vector<signed char> label;  ///< per local region vertex: 0 or 1, the nearer path
  std::vector<int> tets;           ///< the thickened sheet, ascending mesh tet ids
  std::string problem;             ///< empty on success
};

/// `pairs[k]` are the two ends joined by path k. Cost proportional to the region.
ReconnectSheet reconnectSheet(const TetMesh& mesh, const RegionComplex& region,
                              const std::array<std::array<SheetEnd, 2>, 2>& pairs);

/// Exact Euclidean nearest-path labels (distance to the paths' polylines), for measuring the
/// graph partition against.
std::vector<signed char> euclideanLabels(const TetMesh& mesh, const RegionComplex& region,
                                         const std::array<std::vector<int>, 2>& paths);

}  // namespace tfd::core
