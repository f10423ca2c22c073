// RemoveCurves: degenerate curve removal (paper §6.4) inside a ball region, verified by
// re-extraction (core/edit/remove_curves.h).
#include "core/edit/remove_curves.h"

#include "core/region/tet_region.h"
#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Removes the degenerate curves nearest the picked points (paper §6.4): one open curve "
       "with a wedge end and a trisector end (one-curve), an open pure wedge curve with an "
       "open pure trisector curve of the same L/P type (two-curve), or one loop with wedge and "
       "trisector parts (one-loop); other picks are refused with the reason. The field is "
       "rebuilt free of degenerate points inside a region that is a topological ball around "
       "the targets, avoiding every other curve; outside it nothing changes. The result is "
       "verified by extracting the curves again (targets gone, nothing new, every other curve "
       "and vertex unchanged); a failed check retries with a larger region, then fails the "
       "node naming the check.")
      .category("Edit");
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(
      "This field's degenerate curves, when already extracted: the picks name their curves.");
  d.output<core::TensorField>("field").doc("The field without the target curves.");
  d.output<core::DegenerateCurves>("curves").doc(
      "The curves of the new field (extracted with default settings), so edits chain.");
  d.output<core::TetRegion>("region").doc("The tets of the region that was rebuilt.");
  d.param<std::vector<graph::Vec3Param>>("picks")
      .hint(graph::UiHint::Position)
      .doc("One or two points; each names the degenerate curve nearest to it.");
  d.param<double>("region_distance")
      .byDefault(-1)
      .doc(
          "How far the region grows beyond the smallest ball around the targets (a length); "
          "negative: 30 % of the mesh's bounding radius.");
  d.param<int>("retries").byDefault(2).min(0).max(10).doc(
      "Tries with a region grown by 1.5x each after a failed verification.");
}

void cook(graph::CookContext& c) {
  core::RemoveCurvesOptions o;
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("picks"))
    o.picks.push_back(toVec3(p));
  if (o.picks.empty() || o.picks.size() > 2) throw c.paramError("picks", "give one or two points");
  o.regionDistance = c.param<double>("region_distance");
  o.retries = c.param<int>("retries");
  const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr);
  o.curves = curves.get();
  const auto field = c.input<core::TensorField>("field");
  core::RemoveCurvesResult r = core::removeCurves(*field, o, progressOf(c));
  for (const std::string& line : r.report.lines()) c.info(line);
  c.setOutput("field", std::make_shared<const core::TensorField>(std::move(r.field)));
  c.setOutput("curves", std::make_shared<const core::DegenerateCurves>(std::move(r.curves)));
  c.setOutput("region", std::make_shared<const core::TetRegion>(
                            core::TetRegion{field->meshPtr(), std::move(r.regionTets)}));
}

}  // namespace

void registerRemoveCurves(graph::NodeRegistry& r) { r.add("RemoveCurves", 1, declare, cook); }

}  // namespace tfd::nodes
