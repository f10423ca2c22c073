#pragma once
// Core-layer test meshes of curved solids without TetGen (io): structured Kuhn meshes mapped
// smoothly onto a ball or a torus, and box meshes carved to any solid. For core tests, which
// link tfd_core only (tests/CMakeLists.txt).
#include <functional>
#include <memory>

#include "core/surface/surface_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::test {

/// makeBoxMesh(n, n, n, [−1, 1]³) mapped onto the ball of `radius` about the origin by the
/// smooth "spherified cube" map x' = x·√(1 − y²/2 − z²/2 + y²z²/3) (and cyclically), which
/// takes the cube's faces onto the sphere: every boundary vertex lies on the sphere (up to
/// rounding). 6n³ tets; no tet is inverted (checked by TetMesh).
std::shared_ptr<const core::TetMesh> mappedBall(int n, double radius = 1.0);

/// A solid torus about the z axis (ring radius `major`, tube radius `minor`): a structured
/// grid of nAround × n × n cells, periodic around the ring, each tube cross-section the square
/// [−1, 1]² mapped onto the disc by x' = x·√(1 − y²/2), y' = y·√(1 − x²/2). Every boundary
/// vertex lies on the torus surface. 6·nAround·n² tets.
std::shared_ptr<const core::TetMesh> mappedTorus(int nAround, int n, double major = 1.0,
                                                 double minor = 0.4);

/// The tets of makeBoxMesh(n, n, n, lo, hi) whose centroid satisfies `inside`, unused vertices
/// dropped (ids renumbered in ascending order). With `jitter` > 0 interior box vertices are
/// first moved by up to jitter cell sizes (deterministic), so no plane lines up with the grid.
std::shared_ptr<const core::TetMesh> carvedSolid(
    int n, const core::Vec3& lo, const core::Vec3& hi,
    const std::function<bool(const core::Vec3&)>& inside, double jitter = 0.0);

/// Tets joining every triangle of a closed, outward-oriented surface that is star-shaped about
/// `apex` to the apex: a valid tet mesh whose boundary is exactly that surface (e.g. the
/// procedural sphere TetMesh keeps as its boundary), without TetGen.
std::shared_ptr<const core::TetMesh> coneMesh(const core::SurfaceMesh& surface,
                                              const core::Vec3& apex = core::Vec3::Zero());

/// Inside tests for the primitive solids' shapes (centred at the origin, tori in the xy plane):
/// a torus, and the genus-2 union of two such tori side by side along x at ±(major + minor/2).
bool insideTorus(const core::Vec3& p, double major = 1.0, double minor = 0.4);
bool insideDoubleTorus(const core::Vec3& p, double major = 1.0, double minor = 0.4);

}  // namespace tfd::test
