// ExtractDegenerateCurves: the topology of a field (paper §3-4).
#include "core/topology/extract_degenerate_curves.h"

#include <sstream>

#include "core/topology/curve_filter.h"
#include "core/topology/design_point_curves.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

/// boundary_curves: whether curves hugging the boundary are dropped.
const graph::Choices<bool> kBoundaryCurves{{"keep", false}, {"drop", true}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Extracts the degenerate curves of the piecewise-linear field: degenerate points on "
       "every tet face, connected inside each tet, chained into open curves (ending on the "
       "boundary) and loops; each curve classified linear or planar, each point wedge, "
       "trisector or transition.")
      .category("Topology");
  d.input<core::TensorField>("field");
  d.input<core::ConstraintSet>("constraints")
      .optional()
      .doc(
          "The design the field was propagated from: the node then reports the curve through "
          "each degenerate design point (length, type) and warns when it is only a speck.");
  d.output<core::DegenerateCurves>("curves").doc("Classified degenerate curves with stable ids.");
  d.param<int>("arc_samples")
      .byDefault(0)
      .min(0)
      .max(16)
      .doc(
          "Extra points per tet segment sampled on the exact curve: smoother drawing only; "
          "which curves exist, their ids and the filters below do not depend on it.");
  d.param<double>("perturbation")
      .byDefault(1e-7)
      .min(0)
      .max(1e-3)
      .doc(
          "Relative size of the deterministic perturbation that resolves non-generic faces "
          "(e.g. fields whose off-diagonal blocks vanish); 0 switches it off.");
  d.param<std::string>("boundary_curves")
      .choices(kBoundaryCurves)
      .doc(
          "Curves that hug the boundary (every point within the first layer of tets): a "
          "boundary-conforming field (Propagate) has many short ones, as its normal "
          "eigenvalue crosses a tangential one along surface curves; drop them to see the "
          "curves inside the volume.");
  d.param<double>("min_length")
      .byDefault(0)
      .min(0)
      .doc(
          "Drop curves shorter than this (loops: by perimeter, measured through the curve's "
          "points on mesh faces); 0 keeps all.");
}

std::string describePoint(const core::DesignPointCurve& r) {
  std::ostringstream s;
  s << "degenerate point " << r.element << " at (" << r.position.x() << ", " << r.position.y()
    << ", " << r.position.z() << "): ";
  if (!r.pick) {
    s << "no degenerate curve within 2 mean edge lengths";
    return s.str();
  }
  s << "curve " << r.pick->curveId << ", " << core::toString(r.type) << ", length " << r.length;
  if (!r.typeMatches) s << " (designed the other type)";
  return s.str();
}

/// One line per degenerate design point; warnings for specks, missing or mistyped curves.
void reportDesignPoints(graph::CookContext& c, const core::DegenerateCurves& curves,
                        const core::TensorField& field) {
  const auto constraints = c.inputOr<core::ConstraintSet>("constraints", nullptr);
  if (!constraints) return;
  const double h = field.mesh().meanEdgeLength();
  for (const core::DesignPointCurve& r : core::curvesThroughDesignPoints(curves, *constraints, h)) {
    const std::string line = describePoint(r);
    if (!r.pick || !r.typeMatches)
      c.warning(line);
    else if (r.speck)
      c.warning(line + ": a speck shorter than " + std::to_string(int(core::kSpeckEdges)) +
                " mean edge lengths; give the point a larger support (PointConstraint.support)");
    else
      c.info(line);
  }
}

void cook(graph::CookContext& c) {
  core::ExtractOptions o;
  o.arcSamples = c.param<int>("arc_samples");
  o.perturbation = c.param<double>("perturbation");
  const auto field = c.input<core::TensorField>("field");
  core::DegenerateCurves all = core::extractDegenerateCurves(*field, o, progressOf(c));
  for (const std::string& w : all.warnings()) c.warning(w);
  const int onBoundary = core::boundaryCurveCount(all, field->mesh());
  core::CurveFilter filter;
  filter.minLength = c.param<double>("min_length");
  filter.dropBoundary = c.param("boundary_curves", kBoundaryCurves);
  auto curves = std::make_shared<const core::DegenerateCurves>(
      filter.minLength > 0 || filter.dropBoundary ? core::filterCurves(all, field->mesh(), filter)
                                                  : std::move(all));
  std::string info = curves->summary();
  if (onBoundary > 0)
    info += "; " + std::to_string(onBoundary) + " of the extracted curves hug the boundary" +
            (filter.dropBoundary ? " (dropped)" : "");
  if (filter.minLength > 0) info += "; curves shorter than min_length dropped";
  c.info(info);
  reportDesignPoints(c, *curves, *field);
  c.setOutput("curves", std::move(curves));
}

}  // namespace

void registerExtractDegenerateCurves(graph::NodeRegistry& r) {
  r.add("ExtractDegenerateCurves", 1, declare, cook);
}

}  // namespace tfd::nodes
