// PointConstraint: one design element at a point (paper §5, "Design", Equations 2-3).
#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/design/design_element.h"

#include "graph/node_registry.h"
#include "nodes/design/degeneracy_choices.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

enum class Support { Auto, Tet, Radius };
const graph::Choices<Support> kSupports{
    {"auto", Support::Auto}, {"tet", Support::Tet}, {"radius", Support::Radius}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "A design element at a point: a tensor value, or a degenerate tensor with the local "
       "linearisation of Eq. 2 (wedge or trisector pattern, Eq. 3). It fixes the vertices of "
       "the tet that holds it and, by default, every vertex within a few mean edge lengths, so a "
       "degenerate point's curve is long enough to see.")
      .category("Design");
  d.output<core::ConstraintSet>("constraints").doc("One point element.");
  d.param<graph::Vec3Param>("position").hint(graph::UiHint::Position).doc("Where the element is.");
  d.param<std::string>("kind")
      .choices({"tensor", "degenerate"})
      .doc("tensor: a non-degenerate value; degenerate: a degenerate point with a pattern.");
  d.param<std::vector<double>>("tensor")
      .size(6)
      .byDefault({0, 0, 0, 0, 0, 0})
      .doc(
          "kind tensor: components xx, yy, zz, xy, yz, xz in the rotated frame. When all are "
          "zero, `eigenvalues` along the frame axes are used instead.");
  d.param<std::vector<double>>("eigenvalues")
      .size(3)
      .byDefault({1, -0.25, -0.75})
      .doc("kind tensor: eigenvalues along the frame's x, y, z axes (traceless part used).");
  d.param<std::string>("type")
      .choices(kDegenerateTypeChoices)
      .doc(
          "kind degenerate: linear (eigenvalues 2,-1,-1) or planar (1,1,-2); the "
          "non-degenerate eigenvector is the frame's z axis.");
  d.param<std::string>("pattern")
      .choices(kDesignPatternChoices)
      .doc(
          "kind degenerate: the 2D pattern in the degenerate plane (Eq. 3; trisector negates Ty).");
  d.param<graph::Vec3Param>("rotation")
      .hint(graph::UiHint::Angle)
      .doc("Frame rotation: Euler angles in degrees about x, then y, then z.");
  d.param<std::string>("support").choices(kSupports).doc(
      "Which vertices take the element's value: auto, every vertex within 3 mean edge "
      "lengths of the mesh (a degenerate curve a few edges long); tet, only the 4 vertices "
      "of the tet holding the point (the curve may close into a speck); radius, every "
      "vertex within `radius`.");
  d.param<double>("radius").byDefault(0.1).min(0).doc(
      "support radius: fix every vertex within this distance (and the holding tet).");
  d.migration(1, [](graph::Json& params) {
    // typeVersion 1 had no `support`: radius 0 meant the holding tet, > 0 the radius.
    const bool radius = params.contains("radius") && params["radius"].is_number() &&
                        params["radius"].get<double>() > 0;
    params["support"] = radius ? "radius" : "tet";
    if (!radius) params.erase("radius");
  });
}

void cook(graph::CookContext& c) {
  const core::Vec3 position = vec3Param(c, "position");
  const core::Mat3 frame = core::rotationFromEulerDegrees(vec3Param(c, "rotation"));
  core::PointElement element;
  switch (c.param("support", kSupports)) {
    case Support::Auto:
      element.radiusEdges = core::kAutoPointSupportEdges;
      break;
    case Support::Tet:
      break;
    case Support::Radius:
      element.radius = c.param<double>("radius");
      break;
  }
  if (c.param<std::string>("kind") == "degenerate") {
    element.degenerate = true;
    element.field =
        core::makeDegenerateLinearization(position, frame, c.param("type", kDegenerateTypeChoices),
                                          c.param("pattern", kDesignPatternChoices));
  } else {
    const auto t = c.param<std::vector<double>>("tensor");
    const bool explicitTensor = std::any_of(t.begin(), t.end(), [](double v) { return v != 0; });
    if (explicitTensor) {
      element.field.origin = position;
      element.field.frame = frame;
      element.field.value = core::Tensor{t[0], t[1], t[2], t[3], t[4], t[5]}.deviator();
    } else {
      const auto e = c.param<std::vector<double>>("eigenvalues");
      element.field = core::makeTensorLinearization(position, frame, core::Vec3(e[0], e[1], e[2]));
    }
    if (element.field.value.norm() == 0) {
      throw c.paramError(explicitTensor ? "tensor" : "eigenvalues",
                         "the traceless part is zero: a multiple of the identity has no "
                         "directions to design with");
    }
  }
  auto set = std::make_shared<core::ConstraintSet>();
  set->points.push_back(element);
  c.setOutput("constraints", std::move(set));
}

}  // namespace

void registerPointConstraint(graph::NodeRegistry& r) { r.add("PointConstraint", 2, declare, cook); }

}  // namespace tfd::nodes
