#include "core/edit/deform_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/region/curve_tube.h"

namespace tfd::core {
namespace {

/// Arc-length position along a curve (open or closed).
struct CurveArc {
  const DegenerateCurve& curve;
  std::vector<double> s;  ///< s[i]: arc length at point i; s[n] the total (closed: with closing)
  explicit CurveArc(const DegenerateCurve& c) : curve(c), s(c.points.size() + 1, 0) {
    const std::size_t n = c.points.size();
    for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + (c.points[i] - c.points[i - 1]).norm();
    s[n] = s[n - 1] + (c.closed && n > 2 ? (c.points[0] - c.points[n - 1]).norm() : 0.0);
  }
  double total() const { return s.back(); }
  const Vec3& point(std::size_t i) const { return curve.points[i % curve.points.size()]; }
  /// Arc position of the point of the curve nearest to p.
  double project(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity(), at = 0;
    for (std::size_t i = 0; i < curve.segmentCount(); ++i) {
      const double t = closestSegmentParameter(p, point(i), point(i + 1));
      const double d = (p - ((1 - t) * point(i) + t * point(i + 1))).squaredNorm();
      if (d < best) best = d, at = s[i] + t * (s[i + 1] - s[i]);
    }
    return at;
  }
  Vec3 at(double a) const {
    const std::size_t seg = std::min<std::size_t>(
        std::upper_bound(s.begin(), s.end(), a) - s.begin(), curve.segmentCount());
    const std::size_t i = seg == 0 ? 0 : seg - 1;
    const double len = s[i + 1] - s[i];
    const double t = len > 0 ? std::clamp((a - s[i]) / len, 0.0, 1.0) : 0.0;
    return (1 - t) * point(i) + t * point(i + 1);
  }
  /// The curve from arc position a forward to b (wrapping on a loop when b < a).
  std::vector<Vec3> polyline(double a, double b, std::vector<char>* inside = nullptr) const {
    const std::size_t n = curve.points.size();
    std::vector<Vec3> out{at(a)};
    const double end = b >= a ? b : b + total();
    for (std::size_t k = 0; k < 2 * n; ++k) {
      const double sk = k < n ? s[k] : s[k - n] + total();
      if (k >= n && !curve.closed) break;
      if (sk > a && sk < end) {
        out.push_back(point(k));
        if (inside) (*inside)[k % n] = 1;
      }
    }
    out.push_back(at(b));
    return out;
  }
};

double polylineLength(std::span<const Vec3> p) {
  double l = 0;
  for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return l;
}

}  // namespace

std::vector<Vec3> resamplePolyline(std::span<const Vec3> p, int n) {
  std::vector<double> s(p.size(), 0);
  for (std::size_t i = 1; i < p.size(); ++i) s[i] = s[i - 1] + (p[i] - p[i - 1]).norm();
  std::vector<Vec3> out;
  out.reserve(n);
  std::size_t seg = 0;
  for (int k = 0; k < n; ++k) {
    const double a = n == 1 ? 0 : s.back() * k / (n - 1);
    while (seg + 2 < p.size() && s[seg + 1] < a) ++seg;
    const double len = s[seg + 1] - s[seg];
    const double t = len > 0 ? std::clamp((a - s[seg]) / len, 0.0, 1.0) : 0.0;
    out.push_back((1 - t) * p[seg] + t * p[seg + 1]);
  }
  out.back() = p.back();
  return out;
}

double distanceToPolyline(const Vec3& p, std::span<const Vec3> poly, int* segment, double* t) {
  double best = std::numeric_limits<double>::infinity();
  if (poly.size() == 1) best = (p - poly[0]).squaredNorm();
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const double u = closestSegmentParameter(p, poly[i], poly[i + 1]);
    const double d = (p - ((1 - u) * poly[i] + u * poly[i + 1])).squaredNorm();
    if (d < best) {
      best = d;
      if (segment) *segment = int(i);
      if (t) *t = u;
    }
  }
  return std::sqrt(best);
}

DeformPaths deformPaths(const DegenerateCurve& curve, const CurvePick& pick,
                        std::span<const Vec3> target, double spacing) {
  if (target.size() < 2) throw Error("target: give at least two points");
  for (const Vec3& p : target)
    if (!p.allFinite()) throw Error("target: a point is not finite");
  if (curve.points.size() < 2) throw Error("the picked curve has fewer than two points");
  const CurveArc arc(curve);
  double a = arc.project(target.front()), b = arc.project(target.back());
  const double sp = arc.project(pick.position);
  // γ1 runs forward along the curve from lo to hi; on a loop, the arc holding the pick.
  double lo = std::min(a, b), hi = std::max(a, b);
  if (curve.closed && !(sp >= lo && sp <= hi)) std::swap(lo, hi);  // the wrapping arc
  const double along = hi >= lo ? hi - lo : hi + arc.total() - lo;
  if (!(along > spacing))
    throw Error(
        "target: its two ends meet the picked curve at the same place (the segment "
        "between them would be shorter than a quarter of an edge)");
  DeformPaths d;
  d.inGamma1.assign(curve.points.size(), 0);
  std::vector<Vec3> g1 = arc.polyline(lo, hi, &d.inGamma1);
  const bool reversed = lo != std::min(a, b) ? a < b : a > b;  // γ1 must run from a's end
  if (reversed) std::reverse(g1.begin(), g1.end());
  d.target.push_back(g1.front());
  for (const Vec3& p : target)
    if ((p - d.target.back()).norm() > 1e-12) d.target.push_back(p);
  if ((g1.back() - d.target.back()).norm() > 1e-12) d.target.push_back(g1.back());
  if (curve.closed) {
    d.rest.push_back(arc.polyline(hi, lo));
  } else {
    if (lo > 0) d.rest.push_back(arc.polyline(0, lo));
    if (hi < arc.total()) d.rest.push_back(arc.polyline(hi, arc.total()));
  }
  d.length1 = polylineLength(g1), d.length2 = polylineLength(d.target);
  if (!(d.length2 > 0)) throw Error("target: the polyline has zero length");
  const double longer = std::max(d.length1, d.length2);
  const int n = std::max(2, int(std::ceil(longer / spacing)) + 1);
  d.gamma1 = resamplePolyline(g1, n);
  d.gamma2 = resamplePolyline(d.target, n);
  return d;
}

}  // namespace tfd::core
