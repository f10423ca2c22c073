#pragma once
// Helpers shared by the tests/core/topology_*_test.cpp files: random traceless tensors, jittered
// box meshes, linear and analytic fields, and a brute-force degenerate-point search on a face.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "core/structured_mesh.h"
#include "core/tensor.h"
#include "core/tensor_field.h"
#include "core/tet_mesh.h"
#include "core/topology/zheng_pang.h"
#include "tests/support/random_vec3.h"

namespace tfd::core::topology::testing {

inline Tensor randomTraceless(std::mt19937_64& rng, double scale = 1) {
  std::normal_distribution<double> n(0, scale);
  return Tensor::fromVec5({n(rng), n(rng), n(rng), n(rng), n(rng)});
}

/// A box mesh [lo, hi]³ with n³ cells whose interior vertices are moved randomly by up to
/// `jitter` times the cell size (boundary vertices stay, so the box keeps its faces).
inline std::shared_ptr<const TetMesh> jitteredBox(int n, double lo, double hi, double jitter,
                                                  unsigned seed) {
  const auto box = makeBoxMesh(n, n, n, Vec3::Constant(lo), Vec3::Constant(hi));
  std::vector<Vec3> p = box->positions();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const double h = (hi - lo) / n;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (box->isBoundaryVertex(int(i))) continue;
    p[i] += h * test::drawVec3(u, rng);
  }
  return std::make_shared<const TetMesh>(std::move(p), box->tets());
}

using TensorFunction = std::function<Tensor(const Vec3&)>;

inline TensorField sampleField(std::shared_ptr<const TetMesh> mesh, const TensorFunction& f) {
  std::vector<Tensor> values(mesh->vertexCount());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = f(mesh->positions()[i]).deviator();
  return TensorField(std::move(mesh), std::move(values));
}

/// A(p) = A0 + x Gx + y Gy + z Gz.
struct LinearField {
  Tensor a0;
  std::array<Tensor, 3> g;
  Tensor operator()(const Vec3& p) const { return a0 + p.x() * g[0] + p.y() * g[1] + p.z() * g[2]; }
};

inline LinearField randomLinearField(std::mt19937_64& rng) {
  return {randomTraceless(rng), {randomTraceless(rng), randomTraceless(rng), randomTraceless(rng)}};
}

/// Discriminant of t/‖t‖ from the Zheng–Pang sum of squares: accurate to rounding even next
/// to degenerate tensors (4J2³ − 27J3² cancels down to ~1e-16 there).
inline double scaledDiscriminant(const Tensor& t) {
  const double n = t.deviator().norm();
  return n == 0 ? 0 : zhengPangDiscriminant(zhengPangFunctions(t * (1 / n)));
}

/// Weighted Zheng–Pang residual (its squared norm is the discriminant) of a/scale.
inline Eigen::Matrix<double, 7, 1> zpResidual(const Tensor& a, double scale) {
  const ZhengPang f = zhengPangFunctions(a * (1 / scale));
  Eigen::Matrix<double, 7, 1> r;
  const double w = std::sqrt(15.0);
  r << f[0], f[1], f[2], f[3], w * f[4], w * f[5], w * f[6];
  return r;
}

/// Brute-force degenerate points of the face (a, b, c): Gauss–Newton on the Zheng–Pang
/// functions from a dense barycentric grid of starts; returns barycentric coordinates of the
/// converged points (residual ≤ 1e-10 relative) that lie inside the face, merged within 1e-6.
inline std::vector<Vec3> bruteForceFacePoints(const Tensor& a, const Tensor& b, const Tensor& c,
                                              int grid = 16) {
  const double scale = std::max({a.norm(), b.norm(), c.norm()});
  std::vector<Vec3> found;
  if (scale == 0) return found;
  const auto at = [&](double s, double t) { return a + s * (b - a) + t * (c - a); };
  for (int i = 0; i <= grid; ++i) {
    for (int j = 0; i + j <= grid; ++j) {
      double s = double(i) / grid, t = double(j) / grid;
      for (int it = 0; it < 40; ++it) {
        const double h = 1e-5;
        const auto r = zpResidual(at(s, t), scale);
        Eigen::Matrix<double, 7, 2> jac;
        jac.col(0) = (zpResidual(at(s + h, t), scale) - zpResidual(at(s - h, t), scale)) / (2 * h);
        jac.col(1) = (zpResidual(at(s, t + h), scale) - zpResidual(at(s, t - h), scale)) / (2 * h);
        const Eigen::Vector2d step = jac.colPivHouseholderQr().solve(-r);
        if (!step.allFinite()) break;
        const double len = step.norm();
        const Eigen::Vector2d clipped = len > 0.2 ? Eigen::Vector2d(step * (0.2 / len)) : step;
        s += clipped[0], t += clipped[1];
        if (len < 1e-14) break;
      }
      const auto r = zpResidual(at(s, t), scale);
      const Vec3 bary(1 - s - t, s, t);
      if (r.norm() > 1e-10 || bary.minCoeff() < -1e-9) continue;
      bool known = false;
      for (const Vec3& f : found) known = known || (f - bary).norm() < 1e-6;
      if (!known) found.push_back(bary);
    }
  }
  return found;
}

}  // namespace tfd::core::topology::testing
