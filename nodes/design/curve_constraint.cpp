// CurveConstraint: design elements along a sketched curve, applied in a tube around it
// (paper §5, "Design" and "Parameterization").
#include <optional>

#include "core/design/curve_element_builder.h"
#include "graph/node_registry.h"
#include "nodes/design/degeneracy_choices.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::CurveKind> kCurveKinds{{"degenerate", core::CurveKind::Degenerate},
                                                  {"tensor", core::CurveKind::Tensor}};
/// A design pattern, or no value for custom 2x2 blocks.
const graph::Choices<std::optional<core::DegeneratePattern>> kCurvePatterns{
    {"wedge", core::DegeneratePattern::Wedge},
    {"trisector", core::DegeneratePattern::Trisector},
    {"custom", std::nullopt}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Design elements along a curve: control points fitted by a smooth spline, sampled "
       "evenly, each sample with a twist-free (parallel transport) frame whose third axis is "
       "the tangent. Mesh vertices within `radius` of the curve take the value of the nearest "
       "curve point's linearisation; overlapping tubes blend by distance.")
      .category("Design");
  d.output<core::ConstraintSet>("constraints").doc("One curve element (its samples and tube).");
  d.param<std::vector<graph::Vec3Param>>("points")
      .byDefault({{-0.5, 0, 0}, {0, 0.2, 0}, {0.5, 0, 0}})
      .minSize(2)
      .hint(graph::UiHint::Position)
      .doc("Control points [[x, y, z], ...]; at least 2 (3 for a closed curve).");
  d.param<bool>("closed").byDefault(false).doc("A loop through the points (a torus tube).");
  d.param<double>("spacing").byDefault(0.05).min(1e-9).doc(
      "Distance between samples along the spline (adjusted to divide its length).");
  d.param<std::string>("kind")
      .choices(kCurveKinds)
      .doc(
          "degenerate: a degenerate curve with a pattern; tensor: non-degenerate values whose "
          "eigenvectors follow the frame.");
  d.param<std::string>("type")
      .choices(kDegenerateTypeChoices)
      .doc("kind degenerate: linear (eigenvalues 2,-1,-1) or planar (1,1,-2) along the tangent.");
  d.param<std::string>("pattern")
      .choices(kCurvePatterns)
      .doc("kind degenerate: the 2D pattern in the degenerate plane (Eq. 3), or custom blocks.");
  d.param<std::vector<double>>("pattern_tx")
      .size(3)
      .byDefault({1, -1, 0})
      .doc("pattern custom: the 2x2 block of Tx as (uu, vv, uv).");
  d.param<std::vector<double>>("pattern_ty")
      .size(3)
      .byDefault({0, 0, 1})
      .doc("pattern custom: the 2x2 block of Ty as (uu, vv, uv).");
  d.param<std::vector<double>>("eigenvalues")
      .size(3)
      .byDefault({0, -1, 1})
      .doc(
          "kind tensor: eigenvalues along the frame axes (u, v, tangent); default makes the "
          "tangent the major eigenvector.");
  d.param<graph::Vec3Param>("rotation")
      .hint(graph::UiHint::Angle)
      .doc("Rotation of every sample's frame: Euler angles in degrees about x, then y, then z.");
  d.param<double>("radius").byDefault(0.1).min(1e-9).doc("Tube radius around the curve.");
}

core::PatternBlocks blocks(const std::vector<double>& tx, const std::vector<double>& ty) {
  core::PatternBlocks b;
  b.tx << tx[0], tx[2], tx[2], tx[1];
  b.ty << ty[0], ty[2], ty[2], ty[1];
  return b;
}

void cook(graph::CookContext& c) {
  core::CurveOptions o;
  for (const auto& p : c.param<std::vector<graph::Vec3Param>>("points"))
    o.points.push_back(toVec3(p));
  o.closed = c.param<bool>("closed");
  o.spacing = c.param<double>("spacing");
  o.kind = c.param("kind", kCurveKinds);
  o.type = c.param("type", kDegenerateTypeChoices);
  if (const auto pattern = c.param("pattern", kCurvePatterns)) {
    o.pattern = *pattern;
  } else {
    o.customPattern = blocks(c.param<std::vector<double>>("pattern_tx"),
                             c.param<std::vector<double>>("pattern_ty"));
  }
  const auto e = c.param<std::vector<double>>("eigenvalues");
  o.eigenvalues = core::Vec3(e[0], e[1], e[2]);
  o.rotation = vec3Param(c, "rotation");
  o.radius = c.param<double>("radius");
  core::CurveBuildReport report;
  auto set = std::make_shared<core::ConstraintSet>();
  set->curves.push_back(core::buildCurveElement(o, &report));
  c.info(std::to_string(report.samples) + " samples over length " + std::to_string(report.length) +
         (o.closed ? ", holonomy spread " + std::to_string(report.holonomyDegrees) + " deg" : ""));
  c.setOutput("constraints", std::move(set));
}

}  // namespace

void registerCurveConstraint(graph::NodeRegistry& r) { r.add("CurveConstraint", 1, declare, cook); }

}  // namespace tfd::nodes
