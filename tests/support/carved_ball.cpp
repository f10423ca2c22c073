#include "tests/support/carved_ball.h"

#include <vector>

#include "core/structured_mesh.h"

namespace tfd::test {

std::shared_ptr<const core::TetMesh> carvedBall(int n, const core::Vec3& centre, double radius) {
  const core::Vec3 r = core::Vec3::Constant(radius);
  const auto box = core::makeBoxMesh(n, n, n, centre - r, centre + r);
  std::vector<int> newId(box->vertexCount(), -1);
  std::vector<core::TetMesh::Tet> tets;
  for (const auto& t : box->tets()) {
    core::Vec3 c = core::Vec3::Zero();
    for (int v : t) c += box->positions()[v] / 4.0;
    if ((c - centre).norm() < radius) {
      tets.push_back(t);
      for (int v : t) newId[v] = 0;
    }
  }
  std::vector<core::Vec3> positions;
  for (std::size_t v = 0; v < newId.size(); ++v) {
    if (newId[v] == 0) {
      newId[v] = static_cast<int>(positions.size());
      positions.push_back(box->positions()[v]);
    }
  }
  for (auto& t : tets) {
    for (int& v : t) v = newId[v];
  }
  return std::make_shared<const core::TetMesh>(std::move(positions), std::move(tets));
}

}  // namespace tfd::test
