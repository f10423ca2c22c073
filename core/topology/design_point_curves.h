#pragma once
// The degenerate curve through each degenerate design point (paper §5, Eq. 2–3): a designed
// point is meant to be seen, so a node reports the curve's length and type there, and which
// points produced only a speck (a curve about one tet long, closed around the point) or none.
#include <optional>
#include <vector>

#include "core/design/design_element.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct DesignPointCurve {
  int element = -1;  ///< index in ConstraintSet::points
  Vec3 position = Vec3::Zero();
  std::optional<CurvePick> pick;  ///< the curve found at the point; empty when none is near
  double length = 0;              ///< that curve's length (loops: perimeter)
  DegenerateType type = DegenerateType::Linear;  ///< that curve's type
  bool typeMatches = false;                      ///< the curve's type is the designed one
  bool speck = false;                            ///< shorter than kSpeckEdges mean edge lengths
};

/// Curves shorter than this many mean edge lengths count as specks.
inline constexpr double kSpeckEdges = 4.0;

/// For every degenerate point element of `constraints`, the curve of `curves` nearest to it
/// within 2 mean edge lengths (`meanEdge`), in element order. Non-degenerate elements are
/// skipped.
std::vector<DesignPointCurve> curvesThroughDesignPoints(const DegenerateCurves& curves,
                                                        const ConstraintSet& constraints,
                                                        double meanEdge);

}  // namespace tfd::core
