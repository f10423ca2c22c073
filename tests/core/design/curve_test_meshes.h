#pragma once
// Small meshes for the curve and local-smoothing tests: a ball carved from a jittered box mesh
// (a stand-in when no TetGen ball is wanted) and a box with a slot (non-convex).
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "core/structured_mesh.h"
#include "core/tet_mesh.h"
#include "tests/support/random_vec3.h"

namespace tfd::core::testing {

/// Keeps the tets of `mesh` whose centroid satisfies `keep`, renumbering the used vertices
/// (in their original order).
inline std::shared_ptr<const TetMesh> keepTets(const TetMesh& mesh,
                                               const std::function<bool(const Vec3&)>& keep) {
  std::vector<int> remap(mesh.vertexCount(), -1);
  std::vector<TetMesh::Tet> tets;
  for (const auto& t : mesh.tets()) {
    const Vec3 c = 0.25 * (mesh.positions()[t[0]] + mesh.positions()[t[1]] +
                           mesh.positions()[t[2]] + mesh.positions()[t[3]]);
    if (keep(c)) tets.push_back(t);
  }
  for (const auto& t : tets)
    for (int v : t) remap[v] = 0;
  std::vector<Vec3> positions;
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == 0) {
      remap[v] = static_cast<int>(positions.size());
      positions.push_back(mesh.positions()[v]);
    }
  }
  for (auto& t : tets)
    for (int& v : t) v = remap[v];
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

/// Box [−1, 1]³ with n cells per axis, interior vertices jittered by up to `jitter` cell sizes
/// (deterministic), so no mesh plane lines up with the test curves.
inline std::shared_ptr<const TetMesh> jitteredBox(int n, double jitter, unsigned seed = 1) {
  const auto box = makeBoxMesh(n, n, n, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  std::vector<Vec3> positions = box->positions();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 2.0 / n;
  for (auto& p : positions) {
    const Vec3 d = test::drawVec3(u, rng);
    if (p.cwiseAbs().maxCoeff() < 1 - 1e-9) p += jitter * h * d;
  }
  return std::make_shared<const TetMesh>(std::move(positions), box->tets());
}

/// A ball of radius ~0.95 carved from a jittered box mesh (tets whose centroid is inside).
inline std::shared_ptr<const TetMesh> carvedBall(int n, double radius = 0.95) {
  const auto box = jitteredBox(n, 0.15);
  return keepTets(*box, [&](const Vec3& c) { return c.norm() < radius; });
}

}  // namespace tfd::core::testing
