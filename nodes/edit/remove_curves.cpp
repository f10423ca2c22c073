// RemoveCurves: degenerate curve removal (paper §6.4) inside a ball region, verified by
// re-extraction (core/edit/remove_curves.h).
#include "core/edit/remove_curves.h"

#include "graph/node_registry.h"
#include "nodes/edit/edit_node_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Removes the degenerate curves nearest the picked points (paper §6.4): one open curve "
       "with a wedge end and a trisector end (one-curve), an open pure wedge curve with an "
       "open pure trisector curve of the same L/P type (two-curve), one loop with wedge and "
       "trisector parts (one-loop), or a pure wedge loop with a pure trisector loop of the same "
       "type (two-loop: the loops are first reconnected into one mixed loop where they come "
       "closest, as ReconnectCurves does, then that loop is removed; both steps are verified "
       "and reported); other picks are refused with the reason. The field is "
       "rebuilt free of degenerate points inside a region that is a topological ball around "
       "the targets, avoiding every other curve; outside it nothing changes. The result is "
       "verified by extracting the curves again (targets gone, nothing new, every other curve "
       "and vertex unchanged); a failed check retries with a larger region, then fails the "
       "node naming the check.")
      .category("Edit");
  declareEditPorts(
      d, {"This field's degenerate curves, when already extracted: the picks name their "
          "curves.",
          "The field without the target curves.", "The tets of the region that was rebuilt."});
  d.param<std::vector<graph::Vec3Param>>("picks")
      .hint(graph::UiHint::Position)
      .doc("One or two points; each names the degenerate curve nearest to it.");
  declareEditRetryParams(d, "the targets", "a failed verification");
}

void cook(graph::CookContext& c) {
  core::RemoveCurvesOptions o;
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("picks"))
    o.picks.push_back(toVec3(p));
  if (o.picks.empty() || o.picks.size() > 2) throw c.paramError("picks", "give one or two points");
  const EditInputs in = editInputs(c);
  o.regionDistance = in.regionDistance;
  o.retries = in.retries;
  o.curves = in.curves.get();
  publishEdit(c, *in.field, core::removeCurves(*in.field, o, progressOf(c)));
}

}  // namespace

void registerRemoveCurves(graph::NodeRegistry& r) { r.add("RemoveCurves", 1, declare, cook); }

}  // namespace tfd::nodes
