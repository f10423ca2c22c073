#pragma once
// Test meshes with a curved boundary, without TetGen: a structured box mesh carved to a ball.
#include <memory>

#include "core/tet_mesh.h"

namespace tfd::test {

/// The tets of makeBoxMesh(n, n, n, centre − radius·1, centre + radius·1) whose centroid lies
/// inside the ball, with unused vertices dropped (ids renumbered in ascending order). Every
/// point closer than radius − h√3 to the centre is inside the mesh and every point of the mesh
/// is closer than radius + h√3, where h = 2·radius / n is the cube size.
std::shared_ptr<const core::TetMesh> carvedBall(int n, const core::Vec3& centre, double radius);

}  // namespace tfd::test
