#pragma once
// Integrating one hyperstreamline of an eigenvector field (algorithms note §9.3): RK4 whose
// every stage direction is sign-aligned with the previous step's direction (an eigenvector
// field has no sign), with the step halved where the direction turns fast (adaptive step)
// and near the boundary, a degeneracy or a sharp turn before the line is ended there.
#include <functional>
#include <vector>

#include "core/trace/eigen_sampler.h"

namespace tfd::core {

struct TraceOptions {
  double step = 0.01;            ///< RK4 step length (world units)
  double minGap = 0.01;          ///< stop where relativeEigenGap falls below this
  double maxTurnDegrees = 30;    ///< stop where one step turns more than this
  double smoothTurnDegrees = 3;  ///< halve steps that turn more than this (accuracy)
  double maxHalfLength = 1e30;   ///< each half of a line (seed forwards, seed backwards)
  int maxHalvings = 5;           ///< step halvings tried before a line is ended
  long maxSteps = 10'000'000;    ///< a guard: a half line ends (MaxLength) after this many
};

/// The points after the seed in one direction (the seed itself not included).
struct HalfLine {
  std::vector<Vec3> points;
  std::vector<Vec3> eigenvalues;
  LineStop stop = LineStop::Boundary;
};

/// Asked for each new point with its signed arc length from the seed; true ends the line
/// (LineStop::TooClose) before that point.
using ProximityTest = std::function<bool(const Vec3& p, double arc)>;

/// Traces from `seed` (whose sample is `seedSample`) along `sign` × its eigenvector
/// (sign ±1; arc lengths then count with that sign).
HalfLine traceHalfLine(const EigenSampler& sampler, const TraceOptions& options, const Vec3& seed,
                       const EigenSample& seedSample, double sign, const ProximityTest& tooClose);

}  // namespace tfd::core
