#pragma once
// Independent checks for the per-tet topology tests: the linear interpolant of four corner
// tensors evaluated directly (not through TetLinearField), and what a degenerate tensor is.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "core/tensor.h"
#include "tests/core/topology/topology_test_support.h"

namespace tfd::core::topology::testing {

struct TetData {
  std::array<Vec3, 4> corners;
  std::array<Tensor, 4> tensors;
  /// The affine interpolant at any point (extrapolated outside the tet).
  Tensor at(const Vec3& p) const {
    Mat3 e;
    for (int i = 0; i < 3; ++i) e.col(i) = corners[i + 1] - corners[0];
    const Vec3 l = e.fullPivLu().solve(p - corners[0]);
    return tensors[0] * (1 - l.sum()) + tensors[1] * l[0] + tensors[2] * l[1] + tensors[3] * l[2];
  }
  /// Barycentric coordinates of p.
  Eigen::Vector4d barycentric(const Vec3& p) const {
    Mat3 e;
    for (int i = 0; i < 3; ++i) e.col(i) = corners[i + 1] - corners[0];
    const Vec3 l = e.fullPivLu().solve(p - corners[0]);
    return Eigen::Vector4d(1 - l.sum(), l[0], l[1], l[2]);
  }
};

/// A regular-ish tet of size ~1 with random traceless corner tensors.
inline TetData randomTet(std::mt19937_64& rng) {
  TetData t;
  t.corners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.9, 0), Vec3(0.5, 0.3, 0.85)};
  for (auto& a : t.tensors) a = randomTraceless(rng);
  return t;
}

/// Smallest eigenvalue gap relative to the norm: 0 for a degenerate tensor.
inline double relativeGap(const Tensor& t) {
  const EigenDecomposition e = eigenDecompose(t.deviator());
  const double n = std::max(t.deviator().norm(), 1e-300);
  return std::min(e.values[0] - e.values[1], e.values[1] - e.values[2]) / n;
}

/// The eigenvector of the eigenvalue that is not repeated, and whether it is the major one
/// (linear type) or the minor one (planar).
struct Isolated {
  Vec3 vector;
  bool linear;
};
inline Isolated isolatedEigenvector(const Tensor& t) {
  const EigenDecomposition e = eigenDecompose(t.deviator());
  const bool linear = e.values[0] - e.values[1] > e.values[1] - e.values[2];
  return {e.vectors.col(linear ? 0 : 2), linear};
}

}  // namespace tfd::core::topology::testing
