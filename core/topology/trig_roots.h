#pragma once
// Real roots of g(θ) = A0 + A1 cos θ + B1 sin θ + A2 cos 2θ + B2 sin 2θ on [0, 2π): the
// restriction of one conic to the parameterised other (face_solver.h). At most 4 roots.
//
// Method: θ = φ0 + 2 atan x turns g into the quartic Σ c_k x^k (times (1+x²)²), with the
// offset φ0 chosen so that |g(φ0 + π)| is large (no root near x = ∞). The quartic is split into
// monotone pieces at the real roots of its derivative (closed-form cubic), and every sign change
// is bracketed and solved by safeguarded Newton, so no simple root is missed. A stationary point
// where the quartic nearly vanishes without a sign change is returned as a near-double root
// (the curve grazes the face plane), flagged `isolated = false`.
#include <array>

namespace tfd::core::topology {

struct TrigRoot {
  double theta = 0;
  bool isolated = true;  ///< false: a near-double root without a sign change
};

/// Writes the roots into `roots` and returns their number (≤ 4).
int trigQuadraticRoots(double a0, double a1, double b1, double a2, double b2,
                       std::array<TrigRoot, 4>& roots);

/// Real roots of c0 + c1 x + … + c4 x⁴ (c4 ≠ 0) in ascending order, plus near-double
/// stationary points (nearDouble[i] = true). Returns the count (≤ 4).
int quarticRealRoots(const double c[5], double roots[4], bool nearDouble[4]);

}  // namespace tfd::core::topology
