#pragma once
// Chains the per-tet segments into polylines (algorithms note §4, "global") and classifies
// their points (§5): nodes of degree 2 are interior points, degree-1 nodes are open ends
// (normally on the domain boundary), cycles are degenerate loops, and nodes where more than two
// segments meet (non-generic) split curves. Deterministic: walks start at the lowest node id.
#include <cstdint>
#include <vector>

#include "core/topology/degenerate_curves.h"
#include "core/topology/segment_classification.h"

namespace tfd::core::topology {

/// A degenerate point on the mesh skeleton (face, edge or vertex), shared by its tets.
struct CurveNode {
  Vec3 position = Vec3::Zero();
  Vec3 eigenvector = Vec3::UnitZ();
  double sigma = 0;  ///< sign: linear (+) or planar (−)
  PointSource source;
  bool onBoundary = false;  ///< lies on the domain boundary
};

struct AssemblySegment {
  int from = -1, to = -1;
  int tet = -1;
  ArcClassification arc;  ///< oriented from `from` to `to`
};

struct AssemblyResult {
  std::vector<DegenerateCurve> curves;  ///< not yet canonically ordered (ids unset)
  std::int64_t danglingEnds = 0;        ///< open ends not on the boundary
  std::int64_t junctions = 0;           ///< nodes with more than two segments
  std::int64_t mixedTypeCurves = 0;     ///< curves whose points disagree on L/P
};

AssemblyResult assembleCurves(const std::vector<CurveNode>& nodes,
                              const std::vector<AssemblySegment>& segments);

}  // namespace tfd::core::topology
