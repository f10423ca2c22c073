// ExtractDegenerateCurves: the topology of a field (paper §3-4).
#include "core/topology/extract_degenerate_curves.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Extracts the degenerate curves of the piecewise-linear field: degenerate points on "
       "every tet face, connected inside each tet, chained into open curves (ending on the "
       "boundary) and loops; each curve classified linear or planar, each point wedge, "
       "trisector or transition.")
      .category("Topology");
  d.input<core::TensorField>("field");
  d.output<core::DegenerateCurves>("curves");
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
}

void cook(graph::CookContext& c) {
  core::ExtractOptions o;
  o.arcSamples = c.param<int>("arc_samples");
  o.perturbation = c.param<double>("perturbation");
  auto curves = std::make_shared<const core::DegenerateCurves>(
      core::extractDegenerateCurves(*c.input<core::TensorField>("field"), o, progressOf(c)));
  c.info(curves->summary());
  for (const std::string& w : curves->warnings()) c.warning(w);
  c.setOutput("curves", std::move(curves));
}

}  // namespace

void registerExtractDegenerateCurves(graph::NodeRegistry& r) {
  r.add("ExtractDegenerateCurves", 1, declare, cook);
}

}  // namespace tfd::nodes
