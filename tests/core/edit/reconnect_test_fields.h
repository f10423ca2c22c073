#pragma once
// Fields whose reconnection scenario is known (paper §6.2, Fig. 11), for the reconnection tests
// and benchmarks: W = W1 · W2 of removal_test_fields.h has the curves of both factors with their
// own patterns (wedge where (∇f × ∇g) · e > 0), with e (so the non-repeating eigenvector) up.
//  a→  a pure wedge and a pure trisector line            -> two mixed curves (cap and cup)
//  a←  a mixed cap (both ends down) and a mixed cup      -> a wedge and a trisector line
//  b   two pure wedge lines                              -> two wedge lines, ends swapped
//  c   two pure trisector lines                          -> two trisector lines, ends swapped
//  d   a pure wedge line and a mixed cap                 -> a mixed cap and a wedge curve
//  e   two mixed caps side by side (all ends incoming)   -> an outer and an inner cap
// Each comes with picks and the pairing Theorem 6.2 gives, worked out by hand from the
// geometry (which leg joins which). Coordinates for the box [−1, 1]³.
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <vector>

#include "core/topology/degenerate_curves.h"
#include "tests/core/edit/removal_test_fields.h"

namespace tfd::core::testing {

inline Frame upFrame() {
  const Vec3 e = Vec3(0.08, 0.12, 1).normalized();
  const Vec3 u = e.cross(Vec3(0.2, 1, 0.1)).normalized();
  return {e, u, e.cross(u)};
}

/// A mixed cap z = z0 − k (x − x0)², y = y0 (both ends down), wedge on its x > x0 leg.
inline Complex cap(const Vec3& p, double x0, double y0, double z0, double k = 1) {
  const double dx = p.x() - x0;
  return {k * dx * dx + p.z() - z0, p.y() - y0};
}
/// A mixed cup z = z0 + (x − x0)² (both ends up), wedge on its x > x0 leg.
inline Complex cup(const Vec3& p, double z0) { return {p.x() * p.x() - p.z() + z0, p.y()}; }
/// A vertical line through (x0, y0): pure wedge (or trisector when `trisector`).
inline Complex line(const Vec3& p, double x0, double y0, bool trisector = false) {
  const Complex w(p.x() - x0, p.y() - y0);
  return trisector ? std::conj(w) : w;
}

/// w scaled by a positive function to |w| < 1 (so e stays the non-repeating eigenvector):
/// the zero set and the sign of (∇f × ∇g) · e on it do not change.
inline Complex bounded(Complex w) { return w / std::sqrt(1 + std::norm(w)); }

struct Scenario {
  const char* name;
  std::function<Complex(const Vec3&)> W;
  std::array<Vec3, 2> picks;
  /// Whether the end at p (of the first picked segment) joins the end at q (of the second).
  std::function<bool(const Vec3& p, const Vec3& q)> joins;
};

inline const std::vector<Scenario>& scenarios() {
  static const std::vector<Scenario> s = {
      {"a: wedge + trisector -> two mixed",
       [](const Vec3& p) { return 0.5 * line(p, 0.3, 0) * line(p, -0.3, 0, true); },
       {Vec3(0.3, 0, 0), Vec3(-0.3, 0, 0)},
       [](const Vec3& p, const Vec3& q) { return (p.z() > 0) == (q.z() > 0); }},
      {"a: two mixed -> wedge + trisector",
       [](const Vec3& p) { return 0.3 * cap(p, 0, 0, -0.2) * cup(p, 0.2); },
       {Vec3(0, 0, -0.2), Vec3(0, 0, 0.2)},
       [](const Vec3& p, const Vec3& q) { return (p.x() > 0) == (q.x() > 0); }},
      {"b: wedge + wedge",
       [](const Vec3& p) { return 0.5 * line(p, 0.3, 0.1) * line(p, -0.3, -0.1); },
       {Vec3(0.3, 0.1, 0), Vec3(-0.3, -0.1, 0)},
       [](const Vec3& p, const Vec3& q) { return (p.z() > 0) != (q.z() > 0); }},
      {"c: trisector + trisector",
       [](const Vec3& p) { return 0.5 * line(p, 0.3, 0.1, true) * line(p, -0.3, -0.1, true); },
       {Vec3(0.3, 0.1, 0), Vec3(-0.3, -0.1, 0)},
       [](const Vec3& p, const Vec3& q) { return (p.z() > 0) != (q.z() > 0); }},
      {"d: wedge + mixed",
       [](const Vec3& p) { return bounded(line(p, 0.45, 0.25) * cap(p, -0.25, 0, 0.1, 2)); },
       {Vec3(0.45, 0.25, 0.1), Vec3(-0.25, 0, 0.1)},
       // The line's top end joins the cap's wedge (right) leg, its bottom end the left leg.
       [](const Vec3& p, const Vec3& q) { return (p.z() > 0.1) == (q.x() > -0.25); }},
      {"e: mixed + mixed, same side",
       [](const Vec3& p) {
         return bounded(cap(p, -0.4, -0.1, -0.1, 6) * cap(p, 0.4, 0.1, -0.1, 6));
       },
       {Vec3(-0.4, -0.1, -0.1), Vec3(0.4, 0.1, -0.1)},
       // The first cap's right (wedge) leg joins the second's left (trisector) leg.
       [](const Vec3& p, const Vec3& q) { return (p.x() > -0.4) != (q.x() > 0.4); }},
  };
  return s;
}

/// Whether some curve holds both points (within 1e-6 mean edge lengths of `mesh`: the
/// extraction's fallback perturbation may move the ends that much, reconnect_verification.h).
inline bool sameCurveHolds(const DegenerateCurves& curves, const Vec3& a, const Vec3& b,
                           const TetMesh& mesh) {
  const double tolerance = 1e-6 * mesh.meanEdgeLength();
  for (const DegenerateCurve& c : curves.curves()) {
    bool ha = false, hb = false;
    for (const Vec3& p : c.points) {
      ha = ha || (p - a).norm() < tolerance;
      hb = hb || (p - b).norm() < tolerance;
    }
    if (ha && hb) return true;
  }
  return false;
}

}  // namespace tfd::core::testing
