// DeformCurve: degenerate curve deformation (paper §6.1) inside a ball region, verified by
// re-extraction (core/edit/deform_curve.h).
#include "core/edit/deform_curve.h"

#include "core/region/tet_region.h"
#include "graph/node_registry.h"
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
       "and vertex unchanged); a failed check, or a fold-over of the map on the curve, retries "
       "with a larger region, then fails the node naming the check.")
      .category("Edit");
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(
      "This field's degenerate curves, when already extracted: the pick names their curve.");
  d.output<core::TensorField>("field").doc("The field with the curve on its new course.");
  d.output<core::DegenerateCurves>("curves").doc(
      "The curves of the new field (extracted with default settings), so edits chain.");
  d.output<core::TetRegion>("region").doc("The tets of the region that was resampled.");
  d.param<graph::Vec3Param>("pick")
      .hint(graph::UiHint::Position)
      .doc("A point on (or near) the degenerate curve to deform.");
  d.param<std::vector<graph::Vec3Param>>("target")
      .hint(graph::UiHint::Position)
      .doc(
          "The new course of the segment [[x, y, z], ...], at least 2 points; its ends name "
          "where the segment leaves the curve (projected onto it).");
  d.param<double>("region_distance")
      .byDefault(-1)
      .doc(
          "How far the region grows beyond the smallest ball around the segment and the target "
          "(a length); negative: 30 % of the mesh's bounding radius.");
  d.param<int>("retries").byDefault(2).min(0).max(10).doc(
      "Tries with a region grown by 1.5x each after a failed verification or a fold-over.");
}

void cook(graph::CookContext& c) {
  core::DeformCurveOptions o;
  o.pick = vec3Param(c, "pick");
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("target"))
    o.target.push_back(toVec3(p));
  if (o.target.size() < 2) throw c.paramError("target", "give at least two points");
  o.regionDistance = c.param<double>("region_distance");
  o.retries = c.param<int>("retries");
  const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr);
  o.curves = curves.get();
  const auto field = c.input<core::TensorField>("field");
  core::DeformCurveResult r = core::deformCurve(*field, o, progressOf(c));
  for (const std::string& line : r.report.lines()) c.info(line);
  c.setOutput("field", std::make_shared<const core::TensorField>(std::move(r.field)));
  c.setOutput("curves", std::make_shared<const core::DegenerateCurves>(std::move(r.curves)));
  c.setOutput("region", std::make_shared<const core::TetRegion>(
                            core::TetRegion{field->meshPtr(), std::move(r.regionTets)}));
}

}  // namespace

void registerDeformCurve(graph::NodeRegistry& r) { r.add("DeformCurve", 1, declare, cook); }

}  // namespace tfd::nodes
