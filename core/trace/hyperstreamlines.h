#pragma once
// Evenly spaced hyperstreamlines of one eigenvector field (paper §8, Figure 20's noodles;
// algorithms note §9.3): Jobard & Lefer's placement (1997) in 3-D. A seed is accepted only
// `separation` away from every line; a line grows both ways from its seed until it comes
// within `testRatio × separation` of another line (or of itself), reaches a degeneracy, the
// boundary, a sharp turn or its maximum length; new seed candidates sit `separation` away
// from each accepted line, on both sides along two directions perpendicular to it.
//
// Sequential by nature (each line depends on all earlier ones), so the result is the same for
// any thread count: seeds are taken in a fixed order (the given points, then the candidates
// of accepted lines first in first out, then a grid of fallback seeds nearest the centre first).
#include <vector>

#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/trace/polylines.h"

namespace tfd::core {

struct HyperstreamlineOptions {
  EigenFamily family = EigenFamily::Major;
  double separation = 0.1;     ///< d_sep: distance of a new seed from every line
  double testRatio = 0.5;      ///< d_test / d_sep: lines never come closer than d_test
  double step = 0;             ///< RK4 step; 0: min(d_test, mean edge length) / 2
  double minGap = 0.01;        ///< relative eigen-gap below which a line stops (degenerate)
  double maxTurnDegrees = 30;  ///< largest direction change in one step
  double maxLength = 0;        ///< 0: unlimited; else each half (from the seed) gets half
  double minLength = 0;        ///< shorter lines are dropped (their seeds stay free)
  std::vector<Vec3> seeds;     ///< traced first, in order (each at least d_test from lines)
  bool automaticSeeds = true;  ///< then fill the volume with Jobard-Lefer seeding
};

/// Throws core::Error naming the option for a bad separation, ratio, step or angle.
Polylines traceHyperstreamlines(const TensorField& field, const HyperstreamlineOptions& options,
                                const Progress& progress = {});

/// The step used for `options` on `field` (the automatic one when options.step is 0).
double hyperstreamlineStep(const TensorField& field, const HyperstreamlineOptions& options);

}  // namespace tfd::core
