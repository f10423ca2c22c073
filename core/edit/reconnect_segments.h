#pragma once
// The two segments of a degenerate curve reconnection (paper §6.2) inside a region, and their
// four ends: from each picked point the curve is followed both ways through the region's tets
// until it reaches the region's boundary (a curve point whose source is shared with a tet
// outside); those points are the segment's ends. Each end gets its wedge / trisector pattern
// and its incoming / outgoing class by the vectorised non-repeating eigenvector
// (reconnect_pairing.h). Also the points of curves that touch the region (core/edit/edit
// verification asks for the rest of the picked curves to stay away from it).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/edit/reconnect_pairing.h"
#include "core/edit/region_complex.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

/// Where a curve point lies with respect to a region of tets: every tet of its source in the
/// region (inside), some (on the boundary) or none (outside).
enum class PointPlace { Outside, Boundary, Inside };
PointPlace pointPlace(const TetMesh& mesh, const PointSource& source,
                      const std::vector<unsigned char>& inRegion);

/// The mesh vertices of a point's source (a face's three, an edge's two, a vertex, a tet's four).
std::vector<int> sourceVertices(const TetMesh& mesh, const PointSource& source);

struct ReconnectSegments {
  std::array<ReconnectEndpoint, 4> ends;  ///< 0, 1: segment 0 (backward, forward); 2, 3: segment 1
  /// Per segment, the point indices from one end to the other (forward along the curve).
  std::array<std::vector<int>, 2> points;
  std::string problem;  ///< empty when both segments were found and leave the region twice
};

/// `picks`: (curve id, point index) of each segment's picked point, inside the region.
/// `vectorised` must be the non-repeating eigenvector over the region's vertices.
ReconnectSegments findReconnectSegments(const TetMesh& mesh, const DegenerateCurves& curves,
                                        std::span<const std::array<int, 2>, 2> picks,
                                        const std::vector<unsigned char>& inRegion,
                                        const RegionComplex& region,
                                        const VectorisedEigenvector& vectorised);

}  // namespace tfd::core
