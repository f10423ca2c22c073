#pragma once
// A field that runs from degenerate to neutral along x, and an independent (Eigen solver)
// computation of its closeness to degeneracy, for the voxel exporters' density and preview.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/structured_mesh.h"
#include "core/tensor_field.h"

namespace tfd::test {

/// T(x) = (1 − x) L + x N + 0.3 I: L = diag(2, −1, −1) is linear-degenerate (λ2 = λ3), N =
/// diag(1, 0, −1) rotated off the axes is neutral (λ2 = 0). P1 interpolation reproduces it.
inline core::Tensor blendTensor(const core::Vec3& p) {
  const core::Tensor linear{2, -1, -1, 0, 0, 0};
  const core::Tensor neutral = core::Tensor{1, 0, -1, 0, 0, 0}.rotated(
      Eigen::AngleAxisd(0.4, core::Vec3(1, 2, 3).normalized()).toRotationMatrix());
  return (1 - p.x()) * linear + p.x() * neutral + core::Tensor{0.3, 0.3, 0.3, 0, 0, 0};
}

/// Closeness to degeneracy from eigenvalues (Eigen's solver, not tfd's): the deviator's mode
/// 3√6 λ1 λ2 λ3 / ‖A‖³, then (2/π)|asin mode|.
inline double independentCloseness(const core::Tensor& t) {
  Eigen::SelfAdjointEigenSolver<core::Mat3> solver(t.matrix());
  const core::Vec3 l = solver.eigenvalues().array() - solver.eigenvalues().mean();
  const double mode = std::clamp(3 * std::sqrt(6.0) * l.prod() / std::pow(l.norm(), 3), -1.0, 1.0);
  return 2 / std::numbers::pi * std::abs(std::asin(mode));
}

/// blendTensor on the box [0, 1] × [0, 0.3]².
inline core::TensorField blendField() {
  auto mesh = core::makeBoxMesh(6, 2, 2, core::Vec3(0, 0, 0), core::Vec3(1, 0.3, 0.3));
  std::vector<core::Tensor> values;
  for (const auto& p : mesh->positions()) values.push_back(blendTensor(p));
  return core::TensorField(std::move(mesh), std::move(values));
}

}  // namespace tfd::test
