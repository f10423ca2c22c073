#pragma once
// Rational-free parameterisation of the real conic vᵀNv = 0 of ℝP² for a traceless symmetric N
// (algorithms note §3.1 step 4): N has eigenvalues λ1 > 0 > λ3, so the conic is a real oval.
// With the eigenvector qc of the eigenvalue whose sign is alone as chart axis,
//   v(θ) = qc + a cos θ q1 + b sin θ q2,   θ ∈ [0, 2π)
// covers the oval exactly once (v and −v are the same point of ℝP²), and θ(v) inverts it.
#include <cmath>

#include "core/tensor.h"

namespace tfd::core::topology {

struct ConicChart {
  Vec3 qc = Vec3::UnitZ(), q1 = Vec3::UnitX(), q2 = Vec3::UnitY();
  double a = 1, b = 1;
  /// |λ2| / max|λ|: 0 for a line pair (the chart then does not exist).
  double conditioning = 0;

  Vec3 at(double theta) const { return qc + a * std::cos(theta) * q1 + b * std::sin(theta) * q2; }
  /// Chart angle of a direction on the conic (either sign of v).
  double theta(const Vec3& v) const {
    const double sign = v.dot(qc) >= 0 ? 1.0 : -1.0;
    return std::atan2(sign * v.dot(q2) / b, sign * v.dot(q1) / a);
  }
};

/// Chart of the conic of the traceless N; conditioning = 0 when N is (numerically) a line pair
/// or zero, and then a, b are meaningless.
inline ConicChart conicChart(const Mat3& n) {
  const EigenDecomposition e = eigenDecompose(Tensor::fromMatrix(n));
  ConicChart c;
  const double l1 = e.values[0], l2 = e.values[1], l3 = e.values[2];
  const double big = std::max(std::abs(l1), std::abs(l3));
  if (big == 0 || l1 <= 0 || l3 >= 0 || l2 == 0) return c;
  c.conditioning = std::abs(l2) / big;
  if (l2 > 0) {
    c.qc = e.vectors.col(2), c.q1 = e.vectors.col(0), c.q2 = e.vectors.col(1);
    c.a = std::sqrt(-l3 / l1), c.b = std::sqrt(-l3 / l2);
  } else {
    c.qc = e.vectors.col(0), c.q1 = e.vectors.col(1), c.q2 = e.vectors.col(2);
    c.a = std::sqrt(-l1 / l2), c.b = std::sqrt(-l1 / l3);
  }
  return c;
}

}  // namespace tfd::core::topology
