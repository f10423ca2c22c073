#include "core/design/spline.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace tfd::core {
namespace {

std::string format(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// 5-point Gauss–Legendre nodes and weights on [−1, 1].
constexpr double kGaussNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                   0.5384693101056831, 0.9061798459386640};
constexpr double kGaussWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                     0.4786286704993665, 0.2369268850561891};

}  // namespace

Spline::Spline(std::vector<Vec3> controlPoints, bool closed)
    : points_(std::move(controlPoints)), closed_(closed) {
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].allFinite()) {
      throw Error("curve: control point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  if (points_.size() < 2) {
    throw Error("curve: needs at least two control points, got " + std::to_string(points_.size()));
  }
  double scale = 0;
  for (const Vec3& p : points_) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const double tiny = 1e-12 * std::max(scale, 1e-300);
  if (closed_ && points_.size() > 2 && (points_.front() - points_.back()).norm() <= tiny) {
    points_.pop_back();  // the user closed the polygon by repeating the first point
  }
  if (closed_ && points_.size() < 3) {
    throw Error("curve: a closed curve needs at least three distinct control points, got " +
                std::to_string(points_.size()));
  }
  const int n = static_cast<int>(points_.size());
  const int segments = closed_ ? n : n - 1;
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % n;
    if ((points_[j] - points_[i]).norm() <= tiny) {
      throw Error("curve: control points " + std::to_string(i) + " and " + std::to_string(j) +
                  " coincide at " + format(points_[i]));
    }
  }
  // Control point k, with wrap-around (closed) or reflected phantom points (open).
  const auto at = [&](int k) -> Vec3 {
    if (closed_) return points_[((k % n) + n) % n];
    if (k < 0) return 2 * points_[0] - points_[1];
    if (k >= n) return 2 * points_[n - 1] - points_[n - 2];
    return points_[k];
  };
  segments_.resize(segments);
  for (int i = 0; i < segments; ++i) {
    const Vec3 p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
    // Centripetal knot intervals |ΔP|^½; Hermite tangents of the Barry–Goldman pyramid,
    // rescaled to the unit parameter interval of this segment.
    const double d0 = std::sqrt((p1 - p0).norm()), d1 = std::sqrt((p2 - p1).norm()),
                 d2 = std::sqrt((p3 - p2).norm());
    Vec3 m1 = (p2 - p1) / d1, m2 = (p2 - p1) / d1;
    if (d0 > 0) m1 += (p1 - p0) / d0 - (p2 - p0) / (d0 + d1);
    if (d2 > 0) m2 += (p3 - p2) / d2 - (p3 - p1) / (d1 + d2);
    m1 *= d1;
    m2 *= d1;
    segments_[i] = {2 * p1 - 2 * p2 + m1 + m2, -3 * p1 + 3 * p2 - 2 * m1 - m2, m1, p1};
  }
  cumulative_.assign(std::size_t(segments) * kSubintervals + 1, 0.0);
  for (int i = 0; i < segments; ++i) {
    for (int j = 0; j < kSubintervals; ++j) {
      const std::size_t k = std::size_t(i) * kSubintervals + j;
      cumulative_[k + 1] =
          cumulative_[k] + segmentArc(i, double(j) / kSubintervals, double(j + 1) / kSubintervals);
    }
  }
}

int Spline::segmentOf(double u, double& local) const {
  const int segments = segmentCount();
  if (closed_) {
    u = std::fmod(u, double(segments));
    if (u < 0) u += segments;
  } else {
    u = std::clamp(u, 0.0, double(segments));
  }
  const int i = std::min(static_cast<int>(std::floor(u)), segments - 1);
  local = u - i;
  return i;
}

Vec3 Spline::position(double u) const {
  double t;
  const Segment& s = segments_[segmentOf(u, t)];
  return ((s.a * t + s.b) * t + s.c) * t + s.d;
}

Vec3 Spline::derivative(double u) const {
  double t;
  const Segment& s = segments_[segmentOf(u, t)];
  return (3 * s.a * t + 2 * s.b) * t + s.c;
}

double Spline::segmentArc(int segment, double t0, double t1) const {
  const Segment& s = segments_[segment];
  const double half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
  double sum = 0;
  for (int q = 0; q < 5; ++q) {
    const double t = mid + half * kGaussNodes[q];
    sum += kGaussWeights[q] * ((3 * s.a * t + 2 * s.b) * t + s.c).norm();
  }
  return sum * half;
}

double Spline::arcLengthAt(double u) const {
  const int segments = segmentCount();
  if (!closed_ && u >= segments) return length();
  double t;
  const int i = segmentOf(u, t);
  const int j = std::min(static_cast<int>(t * kSubintervals), kSubintervals - 1);
  const double start = double(j) / kSubintervals;
  return cumulative_[std::size_t(i) * kSubintervals + j] + segmentArc(i, start, t);
}

double Spline::parameterAt(double s) const {
  const double total = length();
  s = std::clamp(s, 0.0, total);
  if (s >= total) return segmentCount();
  // Subinterval k holding s: cumulative_[k] ≤ s < cumulative_[k + 1].
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t k = std::min<std::size_t>(
      std::max<std::ptrdiff_t>(it - cumulative_.begin(), 1) - 1, cumulative_.size() - 2);
  const int segment = static_cast<int>(k / kSubintervals);
  const double lo0 = double(k % kSubintervals) / kSubintervals;
  double lo = lo0, hi = lo0 + 1.0 / kSubintervals;
  const double target = s - cumulative_[k];
  const double width = cumulative_[k + 1] - cumulative_[k];
  double t = width > 0 ? lo + (hi - lo) * target / width : lo;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double f = segmentArc(segment, lo0, t) - target;
    if (f > 0)
      hi = t;
    else
      lo = t;
    const double speed = derivative(segment + t).norm();
    double next = speed > 0 ? t - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    if (std::abs(next - t) <= 1e-15) {
      t = next;
      break;
    }
    t = next;
  }
  return segment + t;
}

CurveSamples Spline::sample(double spacing, std::size_t maxSamples) const {
  if (!std::isfinite(spacing) || spacing <= 0) {
    std::ostringstream s;
    s << "curve: spacing must be a positive number, got " << spacing;
    throw Error(s.str());
  }
  const double total = length();
  const double wanted = std::round(total / spacing);
  const double minimum = closed_ ? 3 : 1;
  if (wanted > double(maxSamples)) {
    std::ostringstream s;
    s << "curve: spacing " << spacing << " would need " << wanted
      << " samples on a curve of length " << total << " (at most " << maxSamples << ")";
    throw Error(s.str());
  }
  const int intervals = static_cast<int>(std::max(minimum, wanted));
  CurveSamples out;
  out.closed = closed_;
  out.length = total;
  out.spacing = total / intervals;
  const int count = closed_ ? intervals : intervals + 1;
  const double scale = total / std::max(1, segmentCount());
  for (int k = 0; k < count; ++k) {
    const double s = k == intervals ? total : total * k / intervals;
    const double u = k == intervals ? segmentCount() : parameterAt(s);
    const Vec3 d = derivative(u);
    if (!(d.norm() > 1e-9 * scale)) {
      std::ostringstream m;
      m << "curve: the tangent vanishes at " << format(position(u))
        << " (the curve doubles back on itself near control point " << std::lround(u) << ")";
      throw Error(m.str());
    }
    out.positions.push_back(k == 0                         ? points_.front()
                            : (!closed_ && k == intervals) ? points_.back()
                                                           : position(u));
    out.tangents.push_back(d.normalized());
    out.arcLength.push_back(s);
  }
  if (closed_) out.arcLength.push_back(total);
  return out;
}

}  // namespace tfd::core
