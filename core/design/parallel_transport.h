#pragma once
// Discrete parallel transport and twist-free (Bishop) frames along a curve (Bergou et al. 2008,
// "Discrete Elastic Rods" §4; paper §5, "Design": "At each sample point p, we compute a frame
// based on the method of Bergou et al. [2008]. The first vector in the frame, i.e., the curve
// tangent, ...").
//
// Inputs: the unit tangents at consecutive curve points (spline tangents at the samples, or the
// edge directions of a polyline), open or closed. Outputs: one orthonormal right-handed frame per
// point with columns (t, u, v), v = t × u, and for a closed curve the holonomy: the angle by which
// u comes back rotated about t₀ after being transported once around the loop. For a closed curve
// the holonomy equals, modulo 2π, the signed solid angle enclosed by the tangent indicatrix
// (the spherical polygon t₀ → t₁ → … → t₀ on the unit sphere): transport along a great-circle arc
// is the minimal rotation, and a vector carried around a spherical loop turns by its area
// (Gauss–Bonnet).
#include <span>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// The minimal rotation taking unit vector a to unit vector b: about a × b by the angle between
/// them (identity when a = b), R = I + [w]× + [w]×² / (1 + a·b) with w = a × b. Throws
/// core::Error when a and b are (nearly) opposite, where the axis is undefined.
Mat3 transportRotation(const Vec3& a, const Vec3& b);

/// Signed angle from x to y about the unit axis n, in (−π, π] (x, y ⊥ n).
double signedAngle(const Vec3& x, const Vec3& y, const Vec3& n);

struct BishopOptions {
  /// u at the first point (projected ⊥ t₀ and normalised). When zero or parallel to t₀, the
  /// coordinate axis least aligned with t₀ is projected instead (deterministic).
  Vec3 initialNormal = Vec3::Zero();
  /// Closed curves: rotate frame i about t_i by −holonomy · s_i / s_n so that the twist rate is
  /// uniform and the frame field is periodic (the closing step twists exactly like the others).
  bool distributeHolonomy = true;
  /// Closed curves: s₀ … s_n, the position of each point along the loop followed by the loop's
  /// length (what CurveSamples::arcLength holds). Empty: uniform spacing (s_i = i).
  std::vector<double> arcLength;
};

struct BishopFrames {
  std::vector<Mat3> frames;  ///< columns (t, u, v): tangent first, right-handed, orthonormal
  double holonomy = 0;  ///< closed curves: signed angle about t₀ from u₀ to the transported u
};

/// Bishop frames along the tangents (at least one; a closed curve needs at least two). Throws
/// core::Error when a tangent is not finite and non-zero, or when the curve turns back by 180°
/// between consecutive points (naming them).
BishopFrames bishopFrames(std::span<const Vec3> tangents, bool closed,
                          const BishopOptions& options = {});

}  // namespace tfd::core
