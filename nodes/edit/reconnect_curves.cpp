// ReconnectCurves: degenerate curve reconnection (paper §6.2) inside a ball region, verified by
// re-extraction (core/edit/reconnect_curves.h).
#include "core/edit/reconnect_curves.h"

#include "graph/node_registry.h"
#include "nodes/edit/edit_node_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Cuts two degenerate curve segments open and joins their pieces the other way (paper "
       "§6.2): the segments around the two picked points (on two curves, or two places of one "
       "curve, e.g. a loop to break in two) run through a region that is a topological ball "
       "holding no other degenerate point, and leave it at four ends. Which end joins which "
       "is not a choice: the non-repeating eigenvector, made a vector field in the region, "
       "makes each end incoming or outgoing, and with the ends' wedge / trisector types this "
       "leaves one pairing (Lemma 6.1, Theorem 6.2), given in the info. A sheet between "
       "shortest paths joining the paired ends gets a field without degenerate points, and the "
       "rest of the region is solved again around it; outside the region nothing changes. The "
       "result is verified by extracting the curves again (exactly two new curves in the "
       "region, joining the ends as paired; every other curve and vertex unchanged); a failed "
       "check retries with a larger region, then fails the node naming the check.")
      .category("Edit");
  declareEditPorts(
      d, {"This field's degenerate curves, when already extracted: the picks name their "
          "curves.",
          "The field with the segments reconnected.", "The tets of the region that was rebuilt."});
  d.param<std::vector<graph::Vec3Param>>("picks")
      .hint(graph::UiHint::Position)
      .doc("Two points, one on each segment to reconnect; each names the curve nearest to it.");
  d.param<double>("segment_length")
      .byDefault(-1)
      .doc(
          "How much of each curve around its pick seeds the region (a length; the segment's "
          "ends are where the curve leaves the region); negative: the distance between the "
          "picks.");
  declareEditRetryParams(d, "the two segments", "a failed verification");
}

void cook(graph::CookContext& c) {
  core::ReconnectCurvesOptions o;
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("picks"))
    o.picks.push_back(toVec3(p));
  if (o.picks.size() != 2) throw c.paramError("picks", "give two points");
  o.segmentLength = c.param<double>("segment_length");
  if (o.segmentLength == 0) throw c.paramError("segment_length", "give a non-zero length");
  const EditInputs in = editInputs(c);
  o.regionDistance = in.regionDistance;
  o.retries = in.retries;
  o.curves = in.curves.get();
  publishEdit(c, *in.field, core::reconnectCurves(*in.field, o, progressOf(c)));
}

}  // namespace

void registerReconnectCurves(graph::NodeRegistry& r) { r.add("ReconnectCurves", 1, declare, cook); }

}  // namespace tfd::nodes
