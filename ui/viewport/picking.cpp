#include "ui/viewport/picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/document/graph_document.h"

namespace tfd::ui {

namespace {

const graph::ParamDecl* paramOfKind(const graph::Node& n, std::string_view name,
                                    graph::ParamKind kind) {
  const graph::ParamDecl* d = n.decl().findParam(name);
  return d && d->kind == kind ? d : nullptr;
}

render::Vec3 toVec(const graph::Vec3Param& v) { return {v[0], v[1], v[2]}; }

double round4(double v) { return std::round(v * 1e4) / 1e4 + 0.0; }  // + 0.0: no "-0"

}  // namespace

PickTarget pickTargetFor(const graph::Node& n) {
  using K = graph::ParamKind;
  if (paramOfKind(n, "picks", K::Vec3List))
    return {PickTarget::Kind::CurvePoints, n.name(), "picks"};
  if (paramOfKind(n, "pick", K::Vec3)) return {PickTarget::Kind::CurvePoint, n.name(), "pick"};
  if (const graph::ParamDecl* d = paramOfKind(n, "points", K::Vec3List);
      d && d->hint == graph::UiHint::Position)
    return {PickTarget::Kind::SpacePoints, n.name(), "points"};
  return {};
}

std::vector<render::Vec3> pickedPoints(const graph::Node& n) {
  std::vector<render::Vec3> out;
  const PickTarget t = pickTargetFor(n);
  if (t.kind == PickTarget::Kind::CurvePoint) {
    out.push_back(toVec(std::get<graph::Vec3Param>(n.param(t.param))));
  } else if (t.kind != PickTarget::Kind::None) {
    for (const auto& v : std::get<std::vector<graph::Vec3Param>>(n.param(t.param)))
      out.push_back(toVec(v));
  }
  return out;
}

std::optional<render::Vec3> pickCurvePoint(const render::LineSet& curves,
                                           const render::Camera& camera, int width, int height,
                                           double px, double py, double tolerance) {
  const Eigen::Vector2d click(px, py);
  std::optional<render::Vec3> best;
  double bestScore = std::numeric_limits<double>::infinity();
  const auto& xyz = curves.positions;
  for (std::size_t s = 0; s + 6 <= xyz.size(); s += 6) {
    const render::Vec3 a(xyz[s], xyz[s + 1], xyz[s + 2]);
    const render::Vec3 b(xyz[s + 3], xyz[s + 4], xyz[s + 5]);
    const auto pa = camera.project(a, width, height);
    const auto pb = camera.project(b, width, height);
    if (!pa || !pb) continue;
    const Eigen::Vector2d sa = pa->head<2>(), sb = pb->head<2>();
    const Eigen::Vector2d d = sb - sa;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((click - sa).dot(d) / len2, 0.0, 1.0) : 0.0;
    const double pixels = (sa + t * d - click).norm();
    if (pixels > tolerance) continue;
    // Prefer what is closest on screen, then nearest the eye (depth breaks near-ties).
    const double depth = (*pa)[2] + t * ((*pb)[2] - (*pa)[2]);
    const double score = std::floor(pixels) + depth;
    if (score < bestScore) {
      bestScore = score;
      best = a + t * (b - a);  // screen-space t; fine for short segments
    }
  }
  return best;
}

render::Vec3 pointInSpace(const render::Camera& camera, int width, int height, double px, double py,
                          const render::Vec3& anchor) {
  const render::Ray ray = camera.rayThrough(px, py, width, height);
  const render::Vec3 n = camera.backward();
  const double denom = ray.direction.dot(n);
  if (std::abs(denom) < 1e-12) return anchor;
  const double t = (anchor - ray.origin).dot(n) / denom;
  return ray.origin + t * ray.direction;
}

graph::ParamValue pickedValue(const graph::Node& node, const PickTarget& target,
                              const render::Vec3& p) {
  const graph::Vec3Param v{round4(p.x()), round4(p.y()), round4(p.z())};
  if (target.kind == PickTarget::Kind::CurvePoint) return v;
  auto list = std::get<std::vector<graph::Vec3Param>>(node.param(target.param));
  list.push_back(v);
  return list;
}

bool applyPick(GraphDocument& document, const PickTarget& target, const render::Vec3& p) {
  const graph::Node* n = document.graph().findNode(target.node);
  if (!n || target.kind == PickTarget::Kind::None) return false;
  return document.setParam(target.node, target.param, pickedValue(*n, target, p));
}

}  // namespace tfd::ui
