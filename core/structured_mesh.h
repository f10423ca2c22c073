#pragma once
// Structured tet meshes of a box (Kuhn / Freudenthal split), for tests and analytic examples.
#include <memory>

#include "core/tet_mesh.h"

namespace tfd::core {

/// A box [min, max] split into nx × ny × nz cubes, each cut into 6 positively oriented tets
/// sharing the cube's main diagonal (a conforming mesh). Vertex (i, j, k) has id
/// i + (nx+1)(j + (ny+1)k).
std::shared_ptr<const TetMesh> makeBoxMesh(int nx, int ny, int nz, const Vec3& min,
                                           const Vec3& max);

}  // namespace tfd::core
