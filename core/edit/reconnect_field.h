#pragma once
// The new field of a degenerate curve reconnection (paper §6.2, steps 4 and 5): a
// singularity-free field on the thickened sheet (§6.3, core/edit/singularity_free_field.h),
// held where the sheet meets the region's held boundary and free (natural boundary) towards
// the two parts it separates; then the rest of the region's free vertices solved harmonically
// (Equation 1) with the sheet and the region's boundary held. Each part then holds one pair of
// endpoints, which the new field joins.
//
// The sheet's field is computed on a mesh made of the sheet's tets alone, so that
// singularityFreeField's rule (a vertex on a tet outside its region is held) holds only where
// the sheet meets the outside of the region, not along its faces towards the two parts (which
// the next step re-solves anyway). A trace, if the field has one in the region, is solved as
// one more harmonic scalar. Every vertex that is not a free vertex of the region keeps its
// tensor bitwise. Deterministic for any thread count.
#include <vector>

#include "core/degeneracy.h"
#include "core/edit/singularity_free_field.h"
#include "core/progress.h"
#include "core/region/region_vertices.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct ReconnectFieldReport {
  SingularityFreeReport sheet;    ///< of the sheet's singularity-free field
  std::size_t sheetVertices = 0;  ///< vertices of the sheet's tets
  std::size_t sheetSolved = 0;    ///< of those, free in the region (given new values)
  std::size_t sidesSolved = 0;    ///< the region's other free vertices (harmonic)
  int iterations = 0;             ///< of the harmonic solve
  double relativeResidual = 0;
};

/// `sheetTets`: ascending tet ids inside the region; `rv`: the region's vertices. Throws
/// core::Error when the sheet's field cannot be built (not connected, no held vertex, the
/// eigenvector cannot be oriented on it); core::Cancelled when cancelled.
TensorField reconnectField(const TensorField& field, const std::vector<int>& sheetTets,
                           const RegionVertices& rv, DegenerateType type, const Progress& progress,
                           ReconnectFieldReport& report);

}  // namespace tfd::core
