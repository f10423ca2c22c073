#pragma once
// The incoming / outgoing split of a region's boundary by the vectorised non-repeating
// eigenvector (paper §6.2, Lemma 6.1): a boundary face is incoming where the vector field
// points into the region, outgoing where it points out. By the lemma, a pure wedge (or
// trisector) curve crossing the boundary has one end in each part; a curve with one wedge and
// one trisector part has both ends in the same part. Part of a removal region's report.
#include <span>
#include <string>

#include "core/edit/vectorise_eigenvector.h"
#include "core/tet_mesh.h"

namespace tfd::core {

struct BoundaryFlow {
  std::size_t incomingFaces = 0, outgoingFaces = 0;
  double incomingArea = 0, outgoingArea = 0;
  std::string summary() const;  ///< "boundary: 412 faces incoming (41 %), 590 outgoing"
};

/// Each boundary face of the region (shared with a tet outside or on the domain surface) is
/// classified by the sign of (sum of its vertices' directions) · (outward face normal).
/// `vectorised` must cover every vertex of the region's tets.
BoundaryFlow boundaryFlow(const TetMesh& mesh, std::span<const int> regionTets,
                          const VectorisedEigenvector& vectorised);

}  // namespace tfd::core
