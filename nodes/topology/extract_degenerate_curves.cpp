// ExtractDegenerateCurves: the topology of a field (paper §3-4).
#include "core/topology/extract_degenerate_curves.h"
#include "core/topology/curve_filter.h"

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
  d.output<core::DegenerateCurves>("curves").doc("Classified degenerate curves with stable ids.");
  d.param<int>("arc_samples")
      .byDefault(0)
      .min(0)
      .max(16)
      .doc("Extra points per tet segment sampled on the exact curve (smoother drawing).");
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
      .doc("Drop curves shorter than this (loops: by perimeter); 0 keeps all.");
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
  c.setOutput("curves", std::move(curves));
}

}  // namespace

void registerExtractDegenerateCurves(graph::NodeRegistry& r) {
  r.add("ExtractDegenerateCurves", 1, declare, cook);
}

}  // namespace tfd::nodes
