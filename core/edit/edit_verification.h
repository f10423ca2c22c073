#pragma once
// Verification of a topological edit by re-extraction (the paper's operations "can fail", §9;
// ours check themselves). An edit that changed only the free vertices of a region passes when:
//  1. "outside unchanged": every vertex that is not free keeps its tensor bitwise;
//  2. "untouched curves unchanged": every curve before the edit that passes through no region
//     tet (and is not a target) is there after it: same type, closedness and point count,
//     every point within 1e-12 (and no curve outside the region is new);
//  3. "targets gone": no curve after the edit passes through a region tet near a target;
//  4. "nothing new in the region": no other curve after the edit passes through a region tet.
// Both curve sets must come from the same extraction settings.
#include <span>
#include <string>
#include <vector>

#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct EditVerification {
  bool passed = false;
  std::string failedCheck;  ///< one of the four names above; empty when passed
  std::string detail;       ///< what failed and where
};

/// `freeVertices`: the vertices the edit was allowed to change (ascending); `targetIds`: ids of
/// the targets in `before`; `regionTets`: the region (ascending).
EditVerification verifyEdit(const TensorField& before, const TensorField& after,
                            std::span<const int> freeVertices, std::span<const int> regionTets,
                            const DegenerateCurves& curvesBefore,
                            const DegenerateCurves& curvesAfter, std::span<const int> targetIds);

/// Checks 1 and 2 only (for edits that keep a target in the region, e.g. a deformation, §6.1):
/// on success `matchedAfter` (one flag per curve of `curvesAfter`) marks the curves after the
/// edit that are untouched curves of before; the others pass through the region.
EditVerification verifyOutside(const TensorField& before, const TensorField& after,
                               std::span<const int> freeVertices, std::span<const int> regionTets,
                               const DegenerateCurves& curvesBefore,
                               const DegenerateCurves& curvesAfter, std::span<const int> targetIds,
                               std::vector<char>& matchedAfter);

/// Whether a curve has a point whose source lies in a flagged tet.
bool curveTouchesTets(const TetMesh& mesh, const DegenerateCurve& curve,
                      const std::vector<unsigned char>& tetFlag);

}  // namespace tfd::core
