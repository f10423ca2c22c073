// LocalSmooth: re-solve the harmonic problem inside a region (paper §5, "Local field
// smoothing"); everything outside is left bitwise unchanged.
#include "core/edit/local_smooth.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::SmoothRegionShape> kRegionShapes{
    {"sphere", core::SmoothRegionShape::Sphere},
    {"box", core::SmoothRegionShape::Box},
    {"curve", core::SmoothRegionShape::Curve}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Smooths the field inside a region: a sphere, a box, or the tube around the "
       "degenerate curve nearest `pick`. The region's vertices are re-solved harmonically "
       "with the field on the region's boundary (and on the domain boundary inside it) held "
       "fixed; vertices outside the region keep their exact values. Removes small features "
       "such as tiny degenerate loops.")
      .category("Edit");
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(
      "region curve: this field's degenerate curves, when already extracted (otherwise "
      "they are extracted here).");
  d.output<core::TensorField>("field").doc("The field, re-solved inside the region only.");
  d.param<std::string>("region")
      .choices(kRegionShapes)
      .doc("sphere (center, radius), box (center, size) or curve (pick, radius).");
  d.param<graph::Vec3Param>("center")
      .hint(graph::UiHint::Position)
      .doc("region sphere or box: its centre.");
  d.param<double>("radius").byDefault(0.25).min(1e-9).doc(
      "region sphere: its radius; region curve: the tube radius around the curve.");
  d.param<graph::Vec3Param>("size")
      .byDefault({0.5, 0.5, 0.5})
      .min(1e-9)
      .doc("region box: edge lengths along x, y, z.");
  d.param<graph::Vec3Param>("pick")
      .hint(graph::UiHint::Position)
      .doc("region curve: a point near the degenerate curve to smooth around.");
  d.param<double>("tolerance")
      .byDefault(1e-8)
      .min(1e-14)
      .max(1e-2)
      .doc("Relative residual at which the solve stops.");
}

void cook(graph::CookContext& c) {
  core::LocalSmoothOptions o;
  o.region = c.param("region", kRegionShapes);
  o.center = vec3Param(c, "center");
  o.radius = c.param<double>("radius");
  o.size = vec3Param(c, "size");
  o.pick = vec3Param(c, "pick");
  o.solver.tolerance = c.param<double>("tolerance");
  const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr);
  o.curves = curves.get();
  core::LocalSmoothResult result =
      core::localSmooth(*c.input<core::TensorField>("field"), o, progressOf(c));
  c.info(result.report.summary());
  c.setOutput("field", std::make_shared<const core::TensorField>(std::move(result.field)));
}

}  // namespace

void registerLocalSmooth(graph::NodeRegistry& r) { r.add("LocalSmooth", 1, declare, cook); }

}  // namespace tfd::nodes
