#pragma once
// One eigenvector field of a tensor field, sampled anywhere: the tensor is interpolated
// (barycentric, inside the tet that holds the point) and then decomposed, never the
// eigenvectors (their signs and order are not continuous). Algorithms note §9.3.
#include <optional>

#include "core/tensor_field.h"
#include "core/trace/polylines.h"

namespace tfd::core {

struct EigenSample {
  Vec3 direction;    ///< unit eigenvector of the family; its sign is arbitrary
  Vec3 eigenvalues;  ///< of the interpolated tensor, λ1 ≥ λ2 ≥ λ3
  /// Distance of the family's eigenvalue from the nearest other one over the Frobenius norm of
  /// the deviator (0 for an isotropic tensor): the eigenvector is undefined where it is 0.
  double gap = 0;
};

class EigenSampler {
 public:
  EigenSampler(const TensorField& field, EigenFamily family);
  /// The sample at p, or nothing when p lies outside the mesh.
  std::optional<EigenSample> sample(const Vec3& p) const;
  const TensorField& field() const { return field_; }

 private:
  const TensorField& field_;
  EigenFamily family_;
};

/// The relative eigen-gap of `family` for a tensor with these sorted eigenvalues.
double relativeEigenGap(const Vec3& eigenvalues, EigenFamily family);

}  // namespace tfd::core
