#pragma once
// Two-loop removal (paper §6.4, Fig. 17d): a pure wedge loop cancels with a pure trisector loop
// of the same L/P type, but the region enclosing both is a solid torus, where the angle-based
// field of §6.3 need not be singularity-free. So, as the paper does, it is a composite: step 1
// reconnects the two loops where they come closest (core/edit/reconnect_curves.h; the pairing
// of Theorem 6.2 then joins them into one loop with wedge and trisector parts), step 2 removes
// that loop (one-loop removal, core/edit/remove_curves.h). Each step is verified by
// re-extraction on its own (outside its region nothing changes, every other curve stays), so
// together: both loops gone, every other curve and every vertex outside the two regions
// unchanged.
#include "core/edit/remove_curves.h"

namespace tfd::core {

/// `all`: the curves of `field` extracted with options.extract (each step reuses the
/// extraction before it: step 1 these, step 2 step 1's result's); `a`, `b`: the two picked
/// loops among them (a two-loop scenario); `report` carries the
/// scenario, targets, pick distances and curve count already filled by removeCurves. The
/// result's region is the union of both steps' regions; its report describes step 2 and lists
/// step 1's lines in `reconnection`. Throws RemovalRefused when a step cannot be set up (no
/// ball region), RemovalFailed when a step did not verify (naming the step).
RemoveCurvesResult removeTwoLoops(const TensorField& field, const RemoveCurvesOptions& options,
                                  const DegenerateCurves& all, const DegenerateCurve& a,
                                  const DegenerateCurve& b, RemoveCurvesReport report,
                                  const Progress& progress);

}  // namespace tfd::core
