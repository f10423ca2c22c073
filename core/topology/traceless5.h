#pragma once
// Traceless symmetric tensors as vectors of ℝ⁵ (the Frobenius-orthonormal basis of
// core::Tensor::vec5) and the Veronese map v ↦ vec(v vᵀ − |v|² I/3) used by the degenerate-curve
// extraction (algorithms note §1–2.2).
//
// A traceless tensor is doubly degenerate iff it equals σ b(v) with b(v) = v vᵀ − |v|² I/3; v is
// the non-degenerate eigenvector, σ > 0 linear, σ < 0 planar. For a traceless N,
// ⟨N, b(v)⟩ = vᵀ N v, which turns "b(v) lies in a subspace" into quadratic (conic) equations.
#include <Eigen/Dense>
#include <numbers>

#include "core/tensor.h"

namespace tfd::core::topology {

using Vec5 = Eigen::Matrix<double, 5, 1>;

inline constexpr double kSqrt2 = std::numbers::sqrt2;
inline constexpr double kInvSqrt2 = 1 / std::numbers::sqrt2;
inline constexpr double kInvSqrt6 = 0.40824829046386301637;  // 1/√6

/// Coordinates of the traceless part of t (same basis as Tensor::vec5).
inline Vec5 toVec5(const Tensor& t) {
  Vec5 r;
  r << (t.xx - t.yy) * kInvSqrt2, (t.xx + t.yy - 2 * t.zz) * kInvSqrt6, kSqrt2 * t.xy,
      kSqrt2 * t.xz, kSqrt2 * t.yz;
  return r;
}

/// Coordinates of the traceless part of a symmetric matrix.
inline Vec5 toVec5(const Mat3& m) {
  Vec5 r;
  r << (m(0, 0) - m(1, 1)) * kInvSqrt2, (m(0, 0) + m(1, 1) - 2 * m(2, 2)) * kInvSqrt6,
      kSqrt2 * m(0, 1), kSqrt2 * m(0, 2), kSqrt2 * m(1, 2);
  return r;
}

/// The traceless symmetric matrix with coordinates n.
inline Mat3 matrixOf(const Vec5& n) {
  const double xx = n[0] * kInvSqrt2 + n[1] * kInvSqrt6;
  const double yy = -n[0] * kInvSqrt2 + n[1] * kInvSqrt6;
  const double zz = -2 * n[1] * kInvSqrt6;
  const double xy = n[2] * kInvSqrt2, xz = n[3] * kInvSqrt2, yz = n[4] * kInvSqrt2;
  Mat3 m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return m;
}

/// Tensor with coordinates n.
inline Tensor tensorOf(const Vec5& n) { return Tensor::fromVec5({n[0], n[1], n[2], n[3], n[4]}); }

/// vec(b(v)) with b(v) = v vᵀ − |v|² I/3: homogeneous quadratic, b(−v) = b(v).
inline Vec5 veronese(const Vec3& v) {
  Vec5 r;
  r << (v.x() * v.x() - v.y() * v.y()) * kInvSqrt2,
      (v.x() * v.x() + v.y() * v.y() - 2 * v.z() * v.z()) * kInvSqrt6, kSqrt2 * v.x() * v.y(),
      kSqrt2 * v.x() * v.z(), kSqrt2 * v.y() * v.z();
  return r;
}

/// vec(e vᵀ + v eᵀ): derivative of veronese(v) in direction e.
inline Vec5 veroneseDerivative(const Vec3& v, const Vec3& e) {
  Vec5 r;
  r << 2 * (e.x() * v.x() - e.y() * v.y()) * kInvSqrt2,
      2 * (e.x() * v.x() + e.y() * v.y() - 2 * e.z() * v.z()) * kInvSqrt6,
      kSqrt2 * (e.x() * v.y() + e.y() * v.x()), kSqrt2 * (e.x() * v.z() + e.z() * v.x()),
      kSqrt2 * (e.y() * v.z() + e.z() * v.y());
  return r;
}

/// Two unit vectors (u, w) such that (u, w, e) is a right-handed orthonormal frame (|e| = 1).
inline void completeFrame(const Vec3& e, Vec3& u, Vec3& w) {
  if (std::abs(e.x()) > std::abs(e.y())) {
    u = Vec3(-e.z(), 0, e.x()) / std::hypot(e.x(), e.z());
  } else {
    u = Vec3(0, e.z(), -e.y()) / std::hypot(e.y(), e.z());
  }
  w = e.cross(u);
}

}  // namespace tfd::core::topology
