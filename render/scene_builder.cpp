#include "render/scene_builder.h"

#include "render/colormap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace tfd::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

Rgba fig5(core::DegenerateType type, core::DegeneratePattern pattern) {
  const auto c = core::fig5Colour(type, pattern);
  return {c[0], c[1], c[2], 255};
}

/// A segment's pattern: its first endpoint's, unless that is a transition point.
core::DegeneratePattern segmentPattern(const core::DegenerateCurve& c, std::size_t i,
                                       std::size_t j) {
  if (c.patterns[i] != core::DegeneratePattern::Transition) return c.patterns[i];
  if (c.patterns[j] != core::DegeneratePattern::Transition) return c.patterns[j];
  return core::DegeneratePattern::Wedge;
}

void addFrame(Scene& scene, const Vec3& origin, const core::Mat3& frame, double length) {
  // Shades of the design-element magenta, never a Figure 5 colour: u light, v violet,
  // third axis (a curve's tangent, a degenerate point's non-degenerate direction) white-pink.
  static const Rgba axes[3] = {{255, 150, 255, 255}, {170, 90, 255, 255}, {255, 225, 255, 255}};
  for (int k = 0; k < 3; ++k)
    scene.overlay.add(origin, origin + length * frame.col(k), axes[k], axes[k]);
}

}  // namespace

std::optional<SliceQuantity> parseSliceQuantity(std::string_view name) {
  if (name == "mode") return SliceQuantity::Mode;
  if (name == "degeneracy") return SliceQuantity::Degeneracy;
  if (name == "norm") return SliceQuantity::Norm;
  return std::nullopt;
}

const char* toString(SliceQuantity q) {
  switch (q) {
    case SliceQuantity::Mode:
      return "mode";
    case SliceQuantity::Degeneracy:
      return "degeneracy";
    case SliceQuantity::Norm:
      return "norm";
  }
  return "";
}

void addBoundary(Scene& scene, const core::TetMesh& mesh) {
  std::unordered_map<int, std::uint32_t> local;
  local.reserve(mesh.boundaryVertices().size());
  Surface& s = scene.boundary;
  for (int v : mesh.boundaryVertices()) {
    local[v] = static_cast<std::uint32_t>(s.positions.size() / 3);
    const Vec3& p = mesh.positions()[v];
    const Vec3& n = mesh.vertexNormals()[v];
    for (int i = 0; i < 3; ++i) {
      s.positions.push_back(static_cast<float>(p[i]));
      s.normals.push_back(static_cast<float>(n[i]));
    }
  }
  s.indices.reserve(s.indices.size() + 3 * mesh.boundaryFaces().size());
  for (int f : mesh.boundaryFaces())
    for (int v : mesh.orientedBoundaryFace(f)) s.indices.push_back(local.at(v));
  Bounds b;
  b.extend(mesh.boundsMin());
  b.extend(mesh.boundsMax());
  scene.bounds.extend(b);
}

void addCurves(Scene& scene, const core::DegenerateCurves& curves) {
  for (const core::DegenerateCurve& c : curves.curves()) {
    const std::size_t n = c.points.size();
    for (std::size_t s = 0; s < c.segmentCount(); ++s) {
      const std::size_t i = s, j = (s + 1) % n;
      const Rgba colour = fig5(c.type, segmentPattern(c, i, j));
      scene.curves.add(c.points[i], c.points[j], colour, colour);
    }
    for (std::size_t i = 0; i < n; ++i) {
      scene.bounds.extend(c.points[i]);
      if (c.patterns[i] == core::DegeneratePattern::Transition)
        scene.points.add(c.points[i], fig5(c.type, core::DegeneratePattern::Transition));
    }
  }
}

void addLines(Scene& scene, const core::Polylines& lines) {
  const int k = static_cast<int>(lines.family);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const core::Polyline& l : lines.lines)
    for (const Vec3& e : l.eigenvalues) lo = std::min(lo, e[k]), hi = std::max(hi, e[k]);
  const auto colour = [&](const core::Polyline& l, std::size_t i) {
    const double v = i < l.eigenvalues.size() ? l.eigenvalues[i][k] : lo;
    return sequential(hi > lo ? 0.15 + 0.85 * (v - lo) / (hi - lo) : 0.8);
  };
  for (const core::Polyline& l : lines.lines)
    for (std::size_t i = 0; i < l.points.size(); ++i) {
      scene.bounds.extend(l.points[i]);
      if (i > 0) scene.lines.add(l.points[i - 1], l.points[i], colour(l, i - 1), colour(l, i));
    }
}

void addConstraints(Scene& scene, const core::ConstraintSet& set, double frameLength) {
  for (const core::CurveElement& e : set.curves) {
    const std::size_t n = e.samples.size();
    if (n == 0) continue;
    for (std::size_t i = 0; i + 1 < n + (e.closed ? 1 : 0); ++i)
      scene.overlay.add(e.samples[i].origin, e.samples[(i + 1) % n].origin, kConstraintColour,
                        kConstraintColour);
    const std::size_t every = std::max<std::size_t>(1, n / 12);
    for (std::size_t i = 0; i < n; i += every)
      addFrame(scene, e.samples[i].origin, e.samples[i].frame, frameLength);
    for (const auto& s : e.samples) scene.bounds.extend(s.origin);
  }
  for (const core::PointElement& p : set.points) {
    scene.points.add(p.field.origin, kConstraintColour);
    addFrame(scene, p.field.origin, p.field.frame, 1.5 * frameLength);
    if (p.radius > 0) addSphereOutline(scene, p.field.origin, p.radius, kConstraintColour);
    scene.bounds.extend(p.field.origin);
  }
}

void addSphereOutline(Scene& scene, const Vec3& c, double r, Rgba colour) {
  constexpr int kSteps = 48;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < kSteps; ++i) {
      auto at = [&](int k) {
        const double a = 2 * kPi * k / kSteps;
        Vec3 p = Vec3::Zero();
        p[(axis + 1) % 3] = r * std::cos(a);
        p[(axis + 2) % 3] = r * std::sin(a);
        return Vec3(c + p);
      };
      scene.overlay.add(at(i), at(i + 1), colour, colour);
    }
}

void addBoxOutline(Scene& scene, const Vec3& c, const Vec3& size, Rgba colour) {
  const Vec3 h = 0.5 * size;
  auto corner = [&](int k) {
    return Vec3(c + Vec3(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(), k & 4 ? h.z() : -h.z()));
  };
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4})
      if (!(k & bit)) scene.overlay.add(corner(k), corner(k | bit), colour, colour);
}

void addMarker(Scene& scene, const Vec3& p, Rgba colour) { scene.markers.add(p, colour); }

Scene buildScene(const SceneInput& in) {
  Scene scene;
  if (in.mesh) addBoundary(scene, *in.mesh);
  if (in.curves) addCurves(scene, *in.curves);
  if (in.lines) addLines(scene, *in.lines);
  const double frameLength =
      0.04 * (in.mesh ? (in.mesh->boundsMax() - in.mesh->boundsMin()).norm() : 2.0);
  for (const core::ConstraintSet* set : in.constraints)
    if (set) addConstraints(scene, *set, frameLength);
  if (in.slice && in.field) addSlice(scene, *in.field, *in.slice);
  return scene;
}

}  // namespace tfd::render
