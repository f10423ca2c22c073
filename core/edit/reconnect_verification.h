#pragma once
// Verification of a degenerate curve reconnection (paper §6.2) by re-extraction. Passes when:
//  1–2. "outside unchanged", "untouched curves unchanged": as for every edit
//       (edit_verification.h, verifyOutside) with the two picked curves as targets;
//  3. "two new curves": the curves after the edit pass through the region in exactly two
//     pieces (a piece: a run of points in region tets holding one inside the region; a run
//     only on held boundary faces merely grazes it), each running from one end of the reconnection
//     to another (no loop or piece inside, no piece ending on the domain surface);
//  4. "ends joined as paired": each piece joins two ends that the pairing (Theorem 6.2) joins;
//  5. "targets unchanged outside": off those pieces the curves through the region are the
//     picked curves' points: within 1e-12 where no vertex of the point's tets is a region vertex,
//     within 1e-6 mean edge lengths next to the region (the extraction's fallback perturbation
//     of a held vertex scales with the tensors around it, some of them free, so points there
//     can move by its size; the ends are matched with the same tolerance).
#include <array>
#include <span>
#include <vector>

#include "core/edit/edit_verification.h"
#include "core/edit/reconnect_pairing.h"
#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct ReconnectVerification {
  EditVerification result;
  /// Per piece (when checks 3–4 passed): the curve after the edit and the two ends it joins.
  std::array<int, 2> newCurves{-1, -1};
  std::array<std::array<int, 2>, 2> joins{};
};

ReconnectVerification verifyReconnection(
    const TensorField& before, const TensorField& after, std::span<const int> freeVertices,
    std::span<const int> regionTets, const DegenerateCurves& curvesBefore,
    const DegenerateCurves& curvesAfter, std::span<const int> targetIds,
    std::span<const ReconnectEndpoint, 4> ends, const std::array<int, 4>& partner);

}  // namespace tfd::core
