#pragma once
// The sampling metric of element synthesis (paper §8.2; algorithms note §9.2 step 1), a smooth
// matrix function of the tensor so that it is continuous across degenerate curves.
#include <cmath>

#include "core/tensor.h"

namespace tfd::core {

/// M(A) = exp(−2κ A / s) / r², with A the deviator of the tensor, r the base spacing, κ the
/// anisotropy and s a reference norm of the field (RMS of ‖A‖ over its vertices).
///
/// The matrix exponential of a symmetric matrix is analytic, so M is a smooth function of A
/// everywhere, also where eigenvalues coincide (degenerate curves) and the eigenframe itself
/// jumps. In the eigenframe, M = Σ_k h_k⁻² e_k e_kᵀ with spacing h_k = r·exp(κ λ_k / s) along
/// e_k: samples sit further apart along the major eigenvector than along the minor one. A is
/// traceless, so det M = r⁻⁶ everywhere: the metric turns and stretches the Poisson disks
/// without changing their volume, and the number of samples per volume is set by r alone.
class SpacingMetric {
 public:
  SpacingMetric(double spacing, double anisotropy, double referenceNorm)
      : r_(spacing), kappa_(anisotropy), s_(referenceNorm > 0 ? referenceNorm : 1.0) {}

  /// Spacings h_k along the eigenvectors of a deviator with these eigenvalues.
  Vec3 spacings(const Vec3& eigenvalues) const {
    Vec3 h;
    for (int k = 0; k < 3; ++k) h[k] = r_ * std::exp(kappa_ * eigenvalues[k] / s_);
    return h;
  }
  /// M from the deviator's eigen-decomposition.
  Mat3 metric(const EigenDecomposition& e) const {
    const Vec3 h = spacings(e.values);
    return e.vectors * h.cwiseInverse().cwiseAbs2().asDiagonal() * e.vectors.transpose();
  }
  double spacing() const { return r_; }
  double anisotropy() const { return kappa_; }
  double referenceNorm() const { return s_; }

 private:
  double r_, kappa_, s_;
};

}  // namespace tfd::core
