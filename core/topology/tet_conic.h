#pragma once
// The exact degenerate curve of the linear field inside one tet (algorithms note §2.2, §4).
//
// Inside a tet A(q) = A_c + Σ_k q_k G_k in local coordinates q = (p − centre)/size. With n the
// unit normal of span{A_c, G1, G2, G3} in the 5-D traceless space and N = mat(n), every
// degenerate point has its non-degenerate eigenvector v on the conic vᵀNv = 0, and conversely
// each v on the conic gives b(v) = α A_c + Σ β_k G_k, i.e. the point q = β/α with σ = |v|²/α
// (α = 0: the point is at infinity). The conic chart angle θ therefore parameterises the whole
// degenerate set of the linear field, which is what orders and connects face points (§4).
#include <array>

#include "core/tensor.h"
#include "core/topology/conic_chart.h"
#include "core/topology/traceless5.h"

namespace tfd::core::topology {

/// The linear interpolant of four corner tensors, in the tet's local coordinates.
struct TetLinearField {
  Vec3 centre = Vec3::Zero();
  double size = 1;                        ///< largest corner distance from the centre
  double scale = 0;                       ///< largest corner Frobenius norm (0: zero field)
  Vec5 value = Vec5::Zero();              ///< A(centre) / scale
  std::array<Vec5, 3> gradient{};         ///< ∂A/∂q_k / scale
  Mat3 toBarycentric = Mat3::Identity();  ///< λ1..3 = toBarycentric (q − q0)
  Vec3 q0 = Vec3::Zero();                 ///< local coordinates of corner 0

  TetLinearField(const std::array<Vec3, 4>& corners, const std::array<Tensor, 4>& tensors);
  Vec3 local(const Vec3& p) const { return (p - centre) / size; }
  Eigen::Vector4d barycentric(const Vec3& p) const;
  /// ∂A/∂q_k as matrices (same directions as physical gradients).
  std::array<Mat3, 3> gradientMatrices() const;
};

/// A point of the tet's degenerate curve.
struct ConicPoint {
  bool finite = false;  ///< false when the point is at infinity (α ≈ 0)
  Vec3 position = Vec3::Zero();
  Vec3 eigenvector = Vec3::UnitZ();  ///< unit non-degenerate eigenvector
  double sigma = 0;  ///< A = σ b(v) in units of the field scale; sign: L (+) or P (−)
};

class TetConic {
 public:
  /// Keeps a reference to `field`, which must outlive the conic.
  explicit TetConic(const TetLinearField& field);
  /// False when the field is not generic: span{A_c, G1, G2, G3} has dimension < 4 (e.g. a
  /// block-diagonal or constant field) or the conic is a line pair.
  bool valid() const { return valid_; }
  double theta(const Vec3& v) const { return chart_.theta(v); }
  /// |vᵀNv| for a unit v: 0 on the conic.
  double residual(const Vec3& v) const { return std::abs(v.dot(n_ * v)) / v.squaredNorm(); }
  ConicPoint point(double theta) const;
  const TetLinearField& field() const { return field_; }

 private:
  const TetLinearField& field_;
  bool valid_ = false;
  Mat3 n_ = Mat3::Zero();
  ConicChart chart_;
  Eigen::Matrix<double, 5, 4> q_;  ///< orthonormal basis of the span (first 4 columns of Q)
  Eigen::Matrix4d r_;
  Eigen::Vector4d columnNorms_;
};

}  // namespace tfd::core::topology
