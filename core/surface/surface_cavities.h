#pragma once
// Cavities of a solid bounded by several closed surfaces (a hollow part, a casting with
// voids): a mesher fills the space between facets unless told which pieces hold nothing.
#include <vector>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

/// One point inside each cavity of the solid a closed, consistently oriented surface bounds.
/// The surface's pieces (triangles connected through shared vertices) each enclose a signed
/// volume; the piece of largest |volume| is an outer boundary, and a piece of the opposite sign
/// faces the other way, so it bounds a cavity (a void in the solid, seen from the solid its
/// triangles face away from the material). Its point lies just off the centroid of its
/// largest triangle, on the cavity's side, a thousandth of that triangle's size away. Pieces
/// of the outer boundary's sign (separate solids, solids nested inside cavities) give none.
/// Either overall orientation works.
std::vector<Vec3> cavityPoints(const SurfaceMesh& mesh);

}  // namespace tfd::core
