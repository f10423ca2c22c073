#pragma once
// The vertices of a tet region and which of them an edit may change (paper §6.3, §6.4: "we use
// the tensor values on the boundary of M as constraints"). A region vertex shared with a tet
// outside the region is held (its value is the boundary condition); every other region vertex
// is free, including those only on the domain surface (where the region reaches the surface,
// that part of its boundary is free, like the natural boundary of Eq. 1).
#include <span>
#include <vector>

#include "core/tet_mesh.h"

namespace tfd::core {

struct RegionVertices {
  std::vector<int> vertices;      ///< every vertex of a region tet, ascending
  std::vector<char> held;         ///< one flag per mesh vertex: a region vertex on a tet outside
  std::vector<int> free;          ///< region vertices not held, ascending
  std::size_t freeOnSurface = 0;  ///< free vertices on the domain surface
  std::size_t heldFaces = 0;      ///< boundary faces shared with a tet outside the region
  std::size_t surfaceFaces = 0;   ///< boundary faces on the domain surface
};

/// `tets`: distinct tet ids, any order.
RegionVertices regionVertices(const TetMesh& mesh, std::span<const int> tets);

/// Flags per mesh tet: 1 for the tets listed.
std::vector<unsigned char> tetFlags(const TetMesh& mesh, std::span<const int> tets);

}  // namespace tfd::core
