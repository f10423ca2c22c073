#pragma once
// Which degenerate points on the faces of one tet are joined by the curve inside it
// (algorithms note §4, "θ-ordering with the midpoint rule").
//
// The points are sorted by their conic angle θ (tet_conic.h). Between two θ-consecutive points
// the exact curve does not meet the tet boundary, so each such arc lies wholly inside or wholly
// outside the convex tet: its midpoint decides, and arcs through infinity (α changes sign) are
// outside. This is exact for the PL field, handles any number of points (2, 4, 6, …) and points
// on edges or corners (which touch the tet without entering it), and classifies each arc.
// When the tet's field is not generic (no conic), two points are joined by a chord and more
// are paired greedily by distance, reported as kTetHeuristic.
#include <span>
#include <vector>

#include "core/topology/segment_classification.h"
#include "core/topology/tet_conic.h"

namespace tfd::core::topology {

struct TetNode {
  int id = -1;  ///< global node id
  Vec3 position = Vec3::Zero();
  Vec3 eigenvector = Vec3::UnitZ();
  bool faceInterior = true;  ///< on a face's interior (must be used exactly once)
};

enum TetFlag : unsigned {
  kTetNonGeneric = 1u << 0,  ///< no conic and more than two points
  kTetOdd = 1u << 1,         ///< a face-interior point not joined exactly once
  kTetAmbiguous = 1u << 2,   ///< an arc midpoint on the tet boundary, or coincident points
  kTetHeuristic = 1u << 3,   ///< connected by nearest pairs instead of the conic
  kTetOffConic = 1u << 4,    ///< a point's eigenvector is not on the tet conic
};

struct TetSegment {
  int from = -1, to = -1;  ///< global node ids; the arc runs from `from` to `to`
  bool exactArc = false;   ///< classified on the conic arc (else on the chord)
  ArcClassification arc;
};

struct TetConnection {
  std::vector<TetSegment> segments;
  unsigned flags = 0;
};

TetConnection connectTet(const TetLinearField& field, std::span<const TetNode> nodes,
                         int extraSamples);

}  // namespace tfd::core::topology
