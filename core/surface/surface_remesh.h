#pragma once
// Isotropic surface remeshing onto a known smooth surface (used by the procedural solids).
#include <functional>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

/// Maps a point near the target surface to a point on it.
using SurfaceProjection = std::function<Vec3(const Vec3&)>;

/// Isotropic remeshing (Botsch & Kobbelt 2004): each iteration splits edges longer than 4/3 L,
/// collapses edges shorter than 4/5 L, flips edges to bring vertex valences towards 6 and
/// moves each vertex tangentially to its neighbours' centroid, projecting every new or moved
/// vertex with `project`. Collapses keep the topology (link condition) and never fold a
/// triangle, so a closed, manifold, consistently oriented input stays so, with the same genus.
/// Intended for smooth surfaces (no feature edges are kept). Sequential and deterministic.
void remeshIsotropic(SurfaceMesh& mesh, double edgeLength, const SurfaceProjection& project,
                     int iterations = 6);

}  // namespace tfd::core
