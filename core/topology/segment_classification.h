#pragma once
// Wedge / trisector classification along a degenerate curve and its transition points
// (paper §3; algorithms note §5.2–5.3).
//
// At a degenerate point with unit non-degenerate eigenvector e and (u, w, e) right-handed,
// α = ½(uᵀAu − wᵀAw) and β = uᵀAw vanish to first order along the curve, so the tangent is
// t ∥ ∇α × ∇β, and δ = (∇α × ∇β)·e is the Jacobian of the 2-D field projected on the degenerate
// plane: δ > 0 wedge, δ < 0 trisector, δ = 0 (t ⊥ e) a transition point. δ does not depend on
// the choice of u, w or the sign of e. Inside a tet the gradients are constant, so δ along the
// exact conic arc is a smooth function of θ and its sign changes are found by bisection.
#include <array>
#include <vector>

#include "core/tensor.h"
#include "core/topology/tet_conic.h"

namespace tfd::core::topology {

struct PatternSample {
  double cosine = 0;  ///< δ / |∇α × ∇β| = t̂·e, in [−1, 1]: > 0 wedge, < 0 trisector
  Vec3 tangent = Vec3::Zero();  ///< unit ∇α × ∇β (zero when the gradients are parallel)
};

/// δ and the tangent at a point with eigenvector e of a linear field with gradients g.
PatternSample patternAt(const std::array<Mat3, 3>& gradients, const Vec3& e);

/// A point inside an arc: a transition point or an optional extra sample.
struct ArcPoint {
  double theta = 0;
  Vec3 position = Vec3::Zero();
  Vec3 eigenvector = Vec3::UnitZ();
  Vec3 tangent = Vec3::Zero();  ///< unit, oriented from the arc's start to its end
  double cosine = 0;
  bool transition = false;
};

struct ArcClassification {
  PatternSample start, end;        ///< one-sided, tangents oriented from start to end
  std::vector<ArcPoint> interior;  ///< ordered from start to end
};

/// Classification of the conic arc θ ∈ [thetaStart, thetaEnd] (thetaEnd > thetaStart) of a
/// valid tet conic whose end points have eigenvectors eStart, eEnd. Transition points are
/// located to ~1e-12 in θ; `extraSamples` evenly spaced points are added for smooth drawing.
ArcClassification classifyArc(const TetConic& conic, double thetaStart, double thetaEnd,
                              const Vec3& eStart, const Vec3& eEnd, int extraSamples);

/// Fallback for a non-generic tet: the straight chord from a to b with the end eigenvectors;
/// a sign change of δ puts a transition point where δ interpolates linearly to zero.
ArcClassification classifyChord(const TetLinearField& field, const Vec3& a, const Vec3& b,
                                const Vec3& eStart, const Vec3& eEnd);

}  // namespace tfd::core::topology
