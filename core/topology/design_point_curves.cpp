#include "core/topology/design_point_curves.h"

namespace tfd::core {

std::vector<DesignPointCurve> curvesThroughDesignPoints(const DegenerateCurves& curves,
                                                        const ConstraintSet& constraints,
                                                        double meanEdge) {
  std::vector<DesignPointCurve> out;
  for (std::size_t i = 0; i < constraints.points.size(); ++i) {
    const PointElement& e = constraints.points[i];
    if (!e.degenerate) continue;
    DesignPointCurve r;
    r.element = static_cast<int>(i);
    r.position = e.field.origin;
    auto pick = curves.pick(e.field.origin);
    if (pick && pick->distance <= 2 * meanEdge) {
      const DegenerateCurve& c = curves.curve(pick->curveId);
      r.pick = pick;
      r.length = c.length();
      r.type = c.type;
      // The designed type is that of the element's value: linear (2,−1,−1) has its major
      // eigenvalue standing alone, planar (1,1,−2) its minor one.
      const Vec3 l = eigenDecompose(e.field.value).values;
      const DegenerateType designed =
          l[0] - l[1] > l[1] - l[2] ? DegenerateType::Linear : DegenerateType::Planar;
      r.typeMatches = c.type == designed;
      r.speck = r.length < kSpeckEdges * meanEdge;
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace tfd::core
