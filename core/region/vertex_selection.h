#pragma once
// Vertex selections by geometry (regions named by where they are, never by index): a sphere,
// an axis-aligned box, the tube around a degenerate curve. Each returns ascending vertex ids.
#include <vector>

#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

/// Vertices v with |p(v) − center| ≤ radius.
std::vector<int> verticesInSphere(const TetMesh& mesh, const Vec3& center, double radius);

/// Vertices inside the axis-aligned box of the given centre and edge lengths (boundary included).
std::vector<int> verticesInBox(const TetMesh& mesh, const Vec3& center, const Vec3& size);

/// Vertices in the tube of `radius` around a degenerate curve, reachable through the volume
/// (core/region/curve_tube.h); a curve of one point selects a ball around it.
std::vector<int> verticesAroundCurve(const TetMesh& mesh, const DegenerateCurve& curve,
                                     double radius);

}  // namespace tfd::core
