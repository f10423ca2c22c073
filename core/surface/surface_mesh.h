#pragma once
// Triangle surface meshes: what mesh readers return and TetGen consumes.
#include <array>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

struct SurfaceMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

}  // namespace tfd::core
