#pragma once
// A box of voxels on a regular lattice, and which voxel centres lie inside a tet mesh.
//
// Voxel convention (shared by every voxel output of tfd): voxel (i, j, k) is the cube of side
// `voxelSize` centred on world = origin + voxelSize * (i, j, k), so voxel centres sit on integer
// index coordinates, as in OpenVDB's linear transforms. A grid holds the index box [min, max]
// (inclusive); arrays over it run x fastest, then y, then z.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/progress.h"
#include "core/tensor.h"

namespace tfd::core {

class TetMesh;

struct VoxelGrid {
  double voxelSize = 1;
  Vec3 origin = Vec3::Zero();
  std::array<int, 3> min{0, 0, 0};
  std::array<int, 3> max{-1, -1, -1};

  std::array<int, 3> dims() const {
    return {max[0] - min[0] + 1, max[1] - min[1] + 1, max[2] - min[2] + 1};
  }
  std::size_t count() const {
    const auto d = dims();
    if (d[0] <= 0 || d[1] <= 0 || d[2] <= 0) return 0;
    return std::size_t(d[0]) * std::size_t(d[1]) * std::size_t(d[2]);
  }
  /// World position of the centre of voxel (i, j, k) (lattice indices, not offsets in the box).
  Vec3 centre(int i, int j, int k) const { return origin + voxelSize * Vec3(i, j, k); }
  /// Position of voxel (i, j, k) in arrays over the box (x fastest).
  std::size_t offset(int i, int j, int k) const {
    const auto d = dims();
    return (std::size_t(k - min[2]) * d[1] + std::size_t(j - min[1])) * d[0] +
           std::size_t(i - min[0]);
  }
};

/// 1 for each voxel of `grid` whose centre lies inside the mesh, 0 elsewhere (x fastest).
/// Computed per row of voxels along x from the crossings of the row's line with the boundary
/// faces (parity), with a symbolic perturbation of the line, (y, z) + (ε, ε²), so a line
/// through a boundary edge or vertex is counted once: exact for any closed boundary, up to
/// rounding for centres on the boundary itself. Rows run in parallel; the result does not
/// depend on the thread count. Throws core::Cancelled when `progress` is cancelled.
std::vector<std::uint8_t> insideMask(const TetMesh& mesh, const VoxelGrid& grid,
                                     const Progress& progress = Progress());

}  // namespace tfd::core
