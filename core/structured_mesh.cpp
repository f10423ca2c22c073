#include "core/structured_mesh.h"

#include <algorithm>

#include "core/error.h"

namespace tfd::core {

std::shared_ptr<const TetMesh> makeBoxMesh(int nx, int ny, int nz, const Vec3& min,
                                           const Vec3& max) {
  if (nx < 1 || ny < 1 || nz < 1) throw Error("box mesh needs at least one cell per axis");
  if (!((max - min).array() > 0).all()) throw Error("box mesh needs max > min on every axis");
  const auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  std::vector<Vec3> positions;
  positions.reserve(std::size_t(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        positions.push_back(min + (max - min).cwiseProduct(Vec3(double(i) / nx, double(j) / ny,
                                                                double(k) / nz)));
  // Kuhn split: each permutation of the axes is a monotone path from corner 000 to 111.
  constexpr int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<TetMesh::Tet> tets;
  tets.reserve(std::size_t(nx) * ny * nz * 6);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& path : kPaths) {
          int c[3] = {i, j, k};
          TetMesh::Tet tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[path[s]];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          if (signedVolume(positions[tet[0]], positions[tet[1]], positions[tet[2]],
                           positions[tet[3]]) < 0)
            std::swap(tet[2], tet[3]);
          tets.push_back(tet);
        }
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

}  // namespace tfd::core
