// DeformCurve: degenerate curve deformation (paper §6.1) inside a ball region, verified by
// re-extraction (core/edit/deform_curve.h).
#include "core/edit/deform_curve.h"

#include "graph/node_registry.h"
#include "nodes/edit/edit_node_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Moves a segment of the degenerate curve nearest the pick onto a new course (paper "
       "§6.1). The target's two ends are projected onto the curve: the part of the curve "
       "between them (on a loop, the arc holding the pick) is replaced by the target. The "
       "field is resampled inside a region that is a topological ball holding the old segment "
       "and the target and no other curve, through a map that takes the target to the old "
       "segment (harmonic in the region, the identity on its boundary); outside it nothing "
       "changes. The result is verified by extracting the curves again (one curve in the "
       "region, following the target within the region's mean edge length; every other curve "
       "and vertex unchanged); a failed check retries with a larger region, then fails the "
       "node naming the check; a fold-over of the map on the curve fails it at once (the map "
       "there depends on the target alone, not on the region).")
      .category("Edit");
  declareEditPorts(d,
                   {"This field's degenerate curves, when already extracted: the pick names their "
                    "curve.",
                    "The field with the curve on its new course.",
                    "The tets of the region that was resampled."});
  d.param<graph::Vec3Param>("pick")
      .hint(graph::UiHint::Position)
      .doc("A point on (or near) the degenerate curve to deform.");
  d.param<std::vector<graph::Vec3Param>>("target")
      .hint(graph::UiHint::Position)
      .doc(
          "The new course of the segment [[x, y, z], ...], at least 2 points; its ends name "
          "where the segment leaves the curve (projected onto it).");
  declareEditRetryParams(d, "the segment and the target", "a failed verification");
}

void cook(graph::CookContext& c) {
  core::DeformCurveOptions o;
  o.pick = vec3Param(c, "pick");
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("target"))
    o.target.push_back(toVec3(p));
  if (o.target.size() < 2) throw c.paramError("target", "give at least two points");
  const EditInputs in = editInputs(c);
  o.regionDistance = in.regionDistance;
  o.retries = in.retries;
  o.curves = in.curves.get();
  publishEdit(c, *in.field, core::deformCurve(*in.field, o, progressOf(c)));
}

}  // namespace

void registerDeformCurve(graph::NodeRegistry& r) { r.add("DeformCurve", 1, declare, cook); }

}  // namespace tfd::nodes
