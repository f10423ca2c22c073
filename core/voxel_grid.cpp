#include "core/voxel_grid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/tet_mesh.h"

namespace tfd::core {

namespace {

/// Side of the point (y, z) + (ε, ε²) of the projected edge p → q (on the y-z plane):
/// +1 left, −1 right, 0 only when the edge projects to a point. Called with p, q in ascending
/// vertex order for every face, so faces sharing an edge agree bitwise.
int edgeSide(const Vec3& p, const Vec3& q, double y, double z) {
  const double dy = q.y() - p.y(), dz = q.z() - p.z();
  const double e = dy * (z - p.z()) - dz * (y - p.y());
  if (e != 0) return e > 0 ? 1 : -1;
  // e(y + ε, z + ε²) = e + ε ∂e/∂y + ε² ∂e/∂z with ∂e/∂y = −dz, ∂e/∂z = dy.
  if (dz != 0) return dz < 0 ? 1 : -1;
  if (dy != 0) return dy > 0 ? 1 : -1;
  return 0;
}

/// The x where the line (·, y, z) crosses triangle (a, b, c), when it does (after the
/// perturbation above). Vertices in ascending id order.
bool crossing(const Vec3& a, const Vec3& b, const Vec3& c, double y, double z, double& x) {
  const int ab = edgeSide(a, b, y, z), bc = edgeSide(b, c, y, z), ca = -edgeSide(a, c, y, z);
  if (ab == 0 || ab != bc || bc != ca) return false;
  const double ey = b.y() - a.y(), ez = b.z() - a.z(), fy = c.y() - a.y(), fz = c.z() - a.z();
  const double d = ey * fz - ez * fy;
  if (d == 0) return false;
  const double py = y - a.y(), pz = z - a.z();
  const double u = (py * fz - pz * fy) / d, v = (ey * pz - ez * py) / d;
  x = a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x());
  return true;
}

int floorIndex(double t) { return int(std::floor(t)); }

}  // namespace

std::vector<std::uint8_t> insideMask(const TetMesh& mesh, const VoxelGrid& grid,
                                     const Progress& progress) {
  const auto dims = grid.dims();
  std::vector<std::uint8_t> mask(grid.count(), 0);
  if (mask.empty()) return mask;
  const double h = grid.voxelSize;
  const Vec3& o = grid.origin;
  const auto& pos = mesh.positions();

  // Boundary faces by the z-rows (k) their bounding box may touch (one row of margin: the
  // perturbed line can touch a face at its extreme vertex).
  std::vector<std::vector<int>> byRow(dims[2]);
  for (int f : mesh.boundaryFaces()) {
    const auto& v = mesh.faces()[f];
    const double zlo = std::min({pos[v[0]].z(), pos[v[1]].z(), pos[v[2]].z()});
    const double zhi = std::max({pos[v[0]].z(), pos[v[1]].z(), pos[v[2]].z()});
    const int klo = std::max(grid.min[2], floorIndex((zlo - o.z()) / h));
    const int khi = std::min(grid.max[2], floorIndex((zhi - o.z()) / h) + 1);
    for (int k = klo; k <= khi; ++k) byRow[k - grid.min[2]].push_back(f);
  }

  tbb::parallel_for(0, dims[2], [&](int kk) {
    if (progress.cancelled()) return;
    const int k = grid.min[2] + kk;
    const double z = o.z() + h * k;
    std::vector<std::vector<double>> rows(dims[1]);
    for (int f : byRow[kk]) {
      const auto& v = mesh.faces()[f];  // ascending vertex ids
      const Vec3 &a = pos[v[0]], &b = pos[v[1]], &c = pos[v[2]];
      const double ylo = std::min({a.y(), b.y(), c.y()}), yhi = std::max({a.y(), b.y(), c.y()});
      const int jlo = std::max(grid.min[1], floorIndex((ylo - o.y()) / h));
      const int jhi = std::min(grid.max[1], floorIndex((yhi - o.y()) / h) + 1);
      for (int j = jlo; j <= jhi; ++j) {
        double x;
        if (crossing(a, b, c, o.y() + h * j, z, x)) rows[j - grid.min[1]].push_back(x);
      }
    }
    for (int jj = 0; jj < dims[1]; ++jj) {
      std::vector<double>& xs = rows[jj];
      std::sort(xs.begin(), xs.end());
      std::uint8_t* row = mask.data() + grid.offset(grid.min[0], grid.min[1] + jj, k);
      for (std::size_t m = 0; m + 1 < xs.size(); m += 2) {
        const int ilo = std::max(grid.min[0], int(std::ceil((xs[m] - o.x()) / h)));
        const int ihi = std::min(grid.max[0], floorIndex((xs[m + 1] - o.x()) / h));
        for (int i = ilo; i <= ihi; ++i) row[i - grid.min[0]] = 1;
      }
    }
  });
  progress.throwIfCancelled();
  return mask;
}

}  // namespace tfd::core
