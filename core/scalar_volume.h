#pragma once
// A scalar on a box of voxels with a mask of the voxels that belong to the volume: what
// `GaborNoise` outputs and the voxel exporters write (a `density` grid, EXR slices).
#include <cstdint>
#include <vector>

#include "core/voxel_grid.h"

namespace tfd::core {

struct ScalarVolume {
  VoxelGrid grid;                  ///< voxel size, origin and index box (core/voxel_grid.h)
  std::vector<float> values;       ///< one per voxel of the box, x fastest; 0 outside the mask
  std::vector<std::uint8_t> mask;  ///< 1 where the voxel belongs to the volume (its centre is
                                   ///< inside the mesh), 0 elsewhere

  float at(int i, int j, int k) const { return values[grid.offset(i, j, k)]; }
  bool inside(int i, int j, int k) const { return mask[grid.offset(i, j, k)] != 0; }
  std::size_t activeCount() const {
    std::size_t n = 0;
    for (std::uint8_t m : mask) n += m;
    return n;
  }
};

}  // namespace tfd::core
