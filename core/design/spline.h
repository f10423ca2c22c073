#pragma once
// Smooth curve through user control points and its even arc-length sampling (paper §5,
// "Design": "our system first generates a spline that best captures the sketched curve. The
// spline curve is then subsampled at a set of evenly spaced points on the curve including both
// end points").
//
// The curve is a centripetal Catmull–Rom spline (α = ½, Yuksel et al. 2011): it interpolates
// every control point, is C¹, has no cusp or self-intersection inside a segment, and follows the
// polygon closely (no overshoot loops on unevenly spaced points, unlike a uniform Catmull–Rom
// or a global cubic spline). Segment i joins control points i and i+1 (and, when closed, the last
// point back to the first). An open curve gets phantom end points reflected through its ends
// (P₋₁ = 2P₀ − P₁), so it leaves each end along the end chord; two points give a straight segment
// traversed at constant speed.
#include <span>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// Positions, unit tangents and arc-length positions of evenly spaced curve samples.
struct CurveSamples {
  std::vector<Vec3> positions;
  std::vector<Vec3> tangents;  ///< unit, exact spline derivative direction
  /// Arc length from the start to each sample, plus (closed curves only) one more entry, the
  /// total length, standing for the start reached again.
  std::vector<double> arcLength;
  double length = 0;   ///< total arc length of the spline
  double spacing = 0;  ///< the even spacing actually used (length / number of intervals)
  bool closed = false;
};

class Spline {
 public:
  /// Throws core::Error for fewer than two control points, a closed curve with fewer than three
  /// distinct points, a non-finite coordinate, or two consecutive coincident points (naming
  /// them). A closed curve whose last point repeats the first drops the repetition.
  Spline(std::vector<Vec3> controlPoints, bool closed);

  bool closed() const { return closed_; }
  const std::vector<Vec3>& controlPoints() const { return points_; }
  int segmentCount() const { return static_cast<int>(segments_.size()); }

  /// Curve point at parameter u ∈ [0, segmentCount()]: segment ⌊u⌋ at local u − ⌊u⌋. Control
  /// point i sits at u = i. Parameters outside are clamped (open) or wrapped (closed).
  Vec3 position(double u) const;
  /// dC/du at u (the same parameterisation).
  Vec3 derivative(double u) const;

  double length() const { return cumulative_.back(); }
  /// Arc length from the start to parameter u (Gauss–Legendre quadrature, ~1e-12 relative).
  double arcLengthAt(double u) const;
  /// Parameter u with arcLengthAt(u) = s (Newton iterations safeguarded by bisection).
  double parameterAt(double s) const;

  /// Samples at arc lengths k·h, h = length / n, n = max(1, round(length / spacing)) for an open
  /// curve (n + 1 samples: both ends included) and n = max(3, round(length / spacing)) for a
  /// closed one (n samples; the start is not repeated). Throws core::Error when spacing is not a
  /// finite positive number, when more than `maxSamples` samples would be needed, or when the
  /// tangent vanishes at a sample (the curve doubles back on itself).
  CurveSamples sample(double spacing, std::size_t maxSamples = 1000000) const;

 private:
  struct Segment {
    Vec3 a, b, c, d;  ///< C(t) = ((a t + b) t + c) t + d for t ∈ [0, 1]
  };
  static constexpr int kSubintervals = 16;  ///< per segment, for the arc-length table

  int segmentOf(double u, double& local) const;
  double segmentArc(int segment, double t0, double t1) const;

  std::vector<Vec3> points_;
  bool closed_ = false;
  std::vector<Segment> segments_;
  /// Arc length at every subinterval boundary: entry segment·kSubintervals + j ↔ u = segment +
  /// j / kSubintervals; the last entry is the total length.
  std::vector<double> cumulative_;
};

}  // namespace tfd::core
