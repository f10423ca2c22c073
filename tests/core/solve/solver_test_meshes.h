#pragma once
// Meshes shared by the Laplacian / harmonic solver / propagation tests.
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/structured_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::core::testing {

/// Deterministic pseudo-random number in [−1, 1] for an integer key.
inline double hashUnit(std::uint64_t i) {
  std::uint64_t z = i * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/// A Kuhn box mesh of [−1, 1]³ (n cells per side) whose interior vertices are moved by up to
/// `jitter` cell sizes in random directions: irregular tets, a stiffness matrix with positive
/// off-diagonal entries (not an M-matrix), still positively oriented for jitter ≤ 0.2.
inline std::shared_ptr<const TetMesh> jitteredBox(int n, double jitter = 0.2) {
  auto box = makeBoxMesh(n, n, n, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  std::vector<Vec3> positions = box->positions();
  const double h = 2.0 / n;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (box->isBoundaryVertex(static_cast<int>(v))) continue;
    for (int a = 0; a < 3; ++a) positions[v][a] += jitter * h * hashUnit(3 * v + a);
  }
  return std::make_shared<const TetMesh>(std::move(positions), box->tets());
}

/// A traceless tensor whose components are affine functions of p.
inline Tensor linearTensor(const Vec3& p) {
  Tensor t{0.3 + p.x() - 0.5 * p.y(),
           -0.2 + 0.7 * p.z() + 0.1 * p.x(),
           0,
           0.4 * p.y() - 0.3 * p.z() + 0.05,
           0.9 * p.x() + 0.2,
           -0.6 * p.y() + 0.8 * p.z()};
  t.zz = -(t.xx + t.yy);
  return t;
}

inline double maxDifference(const Tensor& a, const Tensor& b) {
  const auto ca = a.components(), cb = b.components();
  double d = 0;
  for (int i = 0; i < 6; ++i) d = std::max(d, std::abs(ca[i] - cb[i]));
  return d;
}

}  // namespace tfd::core::testing
