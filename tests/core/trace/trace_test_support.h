#pragma once
// Analytic tensor fields on structured box meshes for the trace tests. Linear fields are
// reproduced exactly by the piecewise-linear interpolation, so their closed-form eigenvectors
// are the truth at every point of every tet.
#include <functional>
#include <memory>
#include <random>

#include "core/structured_mesh.h"
#include "core/tensor_field.h"

namespace tfd::core::test {

using FieldFunction = std::function<Tensor(const Vec3&)>;

inline TensorField sampleField(std::shared_ptr<const TetMesh> mesh, const FieldFunction& f) {
  std::vector<Tensor> values;
  values.reserve(mesh->vertexCount());
  for (const Vec3& p : mesh->positions()) values.push_back(f(p));
  return TensorField(std::move(mesh), std::move(values));
}

/// F1 (algorithms note §11): A = [[x−1, y, 0], [y, −x−1, 0], [0, 0, 2]]. Eigenvalues 2 (along
/// z, the major field), −1 + r and −1 − r (r = √(x² + y²)); the medium and minor eigenvectors
/// lie in the xy plane at angles θ/2 and θ/2 + 90° (θ = atan2(y, x)); the z axis is an L-type
/// degenerate line (medium = minor there).
inline Tensor f1(const Vec3& p) { return Tensor{p.x() - 1, -p.x() - 1, 2, p.y(), 0, 0}; }

/// A random traceless linear field A0 + Σ pᵢGᵢ (algorithms note §11, F6).
inline FieldFunction randomLinearField(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, 1);
  const auto random = [&] {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = n(rng);
    return Tensor::deviatorOf(m);
  };
  const Tensor a0 = random(), g0 = random(), g1 = random(), g2 = random();
  return [=](const Vec3& p) { return a0 + p.x() * g0 + p.y() * g1 + p.z() * g2; };
}

/// The unit eigenvector of `column` (0 major, 1 medium, 2 minor) of the exact tensor.
inline Vec3 exactEigenvector(const Tensor& t, int column) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(t.matrix());
  // Eigen sorts ascending.
  return solver.eigenvectors().col(2 - column).normalized();
}

}  // namespace tfd::core::test
