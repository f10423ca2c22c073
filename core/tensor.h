#pragma once
// Symmetric 3x3 tensors and their traceless part (paper section 3).
#include <Eigen/Dense>
#include <array>

namespace tfd::core {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A symmetric 3x3 tensor stored as six components in VTK order (xx, yy, zz, xy, yz, xz).
/// Topology only depends on the deviator, so most of tfd keeps tensors traceless.
struct Tensor {
  double xx = 0, yy = 0, zz = 0, xy = 0, yz = 0, xz = 0;

  static Tensor fromMatrix(const Mat3& m);  ///< symmetric part of m
  /// Traceless part of the symmetric part of m (the deviator A = T - tr(T)/3 I).
  static Tensor deviatorOf(const Mat3& m) { return fromMatrix(m).deviator(); }
  /// Inverse of vec5(): components in the orthonormal traceless basis below.
  static Tensor fromVec5(const std::array<double, 5>& v);

  Mat3 matrix() const;
  double trace() const { return xx + yy + zz; }
  Tensor deviator() const;
  double norm() const;  ///< Frobenius norm
  /// Components in the Frobenius-orthonormal basis of traceless tensors
  /// E1 = diag(1,-1,0)/√2, E2 = diag(1,1,-2)/√6, E3..E5 = (xy, xz, yz) symmetric units/√2.
  /// The trace part is dropped. Frobenius products of deviators become dot products.
  std::array<double, 5> vec5() const;
  /// Components as an array in VTK order.
  std::array<double, 6> components() const { return {xx, yy, zz, xy, yz, xz}; }
  static Tensor fromComponents(const std::array<double, 6>& c) {
    return {c[0], c[1], c[2], c[3], c[4], c[5]};
  }
  /// R T Rᵀ: the same tensor expressed after rotating space by R.
  Tensor rotated(const Mat3& r) const { return fromMatrix(r * matrix() * r.transpose()); }

  Tensor& operator+=(const Tensor& o);
  Tensor& operator-=(const Tensor& o);
  Tensor& operator*=(double s);
  friend Tensor operator+(Tensor a, const Tensor& b) { return a += b; }
  friend Tensor operator-(Tensor a, const Tensor& b) { return a -= b; }
  friend Tensor operator*(Tensor a, double s) { return a *= s; }
  friend Tensor operator*(double s, Tensor a) { return a *= s; }
  friend bool operator==(const Tensor&, const Tensor&) = default;
};

/// Eigenvalues in descending order λ1 ≥ λ2 ≥ λ3, eigenvectors as the columns of a right-handed
/// orthonormal matrix (column i belongs to values[i]).
struct EigenDecomposition {
  Vec3 values;
  Mat3 vectors;
};

/// Closed-form eigen-decomposition that stays accurate near repeated eigenvalues: the
/// eigenvalues from the trigonometric solution of the characteristic cubic, the eigenvector of
/// the most isolated eigenvalue from cross products, the other two inside its orthogonal
/// complement. Residual ‖Tv − λv‖ is at rounding level of ‖T‖ for any input.
EigenDecomposition eigenDecompose(const Tensor& t);

/// Whether traces up to `maxTrace` in absolute value, among tensors of norms up to `maxNorm`,
/// are more than rounding: above 1e-12 of the norm (a traceless design's traces are ~1e-16 of
/// it). Edits solve the trace as one more harmonic column only then; rounding-level traces
/// would only slow that solve down (its tolerance is relative to them), and the tensors solved
/// without them are traceless.
inline bool traceBeyondRounding(double maxTrace, double maxNorm) {
  return maxTrace > 1e-12 * maxNorm;
}

/// Linear (λ2 < 0), planar (λ2 > 0) or neutral (λ2 = 0) by the deviator's middle eigenvalue.
enum class TensorType { Linear, Planar, Neutral };
/// `relativeTolerance` is compared with |λ2| / ‖A‖ to call a tensor neutral.
TensorType classify(const Tensor& t, double relativeTolerance = 1e-12);
const char* toString(TensorType type);

/// Discriminant of the deviator, (λ1−λ2)²(λ2−λ3)²(λ3−λ1)² = 4 J2³ − 27 J3²; zero exactly on
/// degenerate tensors.
double discriminant(const Tensor& t);
/// Discriminant of the deviator scaled by ‖A‖⁶, in [0, 1/2]: scale-free degeneracy measure.
double normalizedDiscriminant(const Tensor& t);
/// Mode 3√6 det(A/‖A‖) ∈ [−1, 1]: +1 linear-degenerate, −1 planar-degenerate, 0 for a zero A.
double mode(const Tensor& t);

}  // namespace tfd::core
