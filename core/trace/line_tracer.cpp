#include "core/trace/line_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tfd::core {
namespace {

struct Stage {
  bool ok = false;
  LineStop stop = LineStop::Boundary;
  Vec3 k = Vec3::Zero();
  EigenSample sample;
};

/// The field's direction at p, sign-aligned with the previous step direction d.
Stage stageAt(const EigenSampler& sampler, const Vec3& p, const Vec3& d, double minGap,
              double cosMaxTurn) {
  Stage s;
  const auto sample = sampler.sample(p);
  if (!sample) return s;  // Boundary
  if (sample->gap < minGap) {
    s.stop = LineStop::Degenerate;
    return s;
  }
  s.k = sample->direction.dot(d) < 0 ? Vec3(-sample->direction) : sample->direction;
  if (s.k.dot(d) < cosMaxTurn) {
    s.stop = LineStop::SharpTurn;
    return s;
  }
  s.ok = true;
  s.sample = *sample;
  return s;
}

/// One RK4 step of length h from x along d (k1 known); the sample at the new point on success.
Stage rk4Step(const EigenSampler& sampler, const Vec3& x, const Vec3& d, const Vec3& k1, double h,
              double minGap, double cosMaxTurn, Vec3& next) {
  const Stage s2 = stageAt(sampler, x + 0.5 * h * k1, d, minGap, cosMaxTurn);
  if (!s2.ok) return s2;
  const Stage s3 = stageAt(sampler, x + 0.5 * h * s2.k, d, minGap, cosMaxTurn);
  if (!s3.ok) return s3;
  const Stage s4 = stageAt(sampler, x + h * s3.k, d, minGap, cosMaxTurn);
  if (!s4.ok) return s4;
  const Vec3 dir = (k1 + 2 * s2.k + 2 * s3.k + s4.k).normalized();
  next = x + h * dir;
  // The new point's own direction becomes the next step's k1; it must also pass the tests
  // against this step's direction.
  return stageAt(sampler, next, dir, minGap, cosMaxTurn);
}

}  // namespace

HalfLine traceHalfLine(const EigenSampler& sampler, const TraceOptions& options, const Vec3& seed,
                       const EigenSample& seedSample, double sign, const ProximityTest& tooClose) {
  HalfLine out;
  const double cosMaxTurn = std::cos(options.maxTurnDegrees * std::numbers::pi / 180);
  const double cosSmoothTurn = std::cos(
      std::min(options.smoothTurnDegrees, options.maxTurnDegrees) * std::numbers::pi / 180);
  Vec3 x = seed;
  Vec3 k1 = sign * seedSample.direction;
  Vec3 d = k1;
  double arc = 0;
  for (;;) {
    if (arc + options.step > options.maxHalfLength ||
        static_cast<long>(out.points.size()) >= options.maxSteps) {
      out.stop = LineStop::MaxLength;
      return out;
    }
    double h = options.step;
    Vec3 next;
    Stage s;
    // Halve the step where it fails (boundary, degeneracy, sharp turn) and, for accuracy,
    // where the direction turns more than `smoothTurn` within it (adaptive step).
    for (int halving = 0;; ++halving) {
      s = rk4Step(sampler, x, d, k1, h, options.minGap, cosMaxTurn, next);
      if (halving == options.maxHalvings) break;
      if (s.ok && s.k.dot(k1) >= cosSmoothTurn) break;
      h *= 0.5;
    }
    if (!s.ok) {
      out.stop = s.stop;
      return out;
    }
    const double nextArc = arc + h;
    if (tooClose && tooClose(next, sign * nextArc)) {
      out.stop = LineStop::TooClose;
      return out;
    }
    d = (next - x).normalized();
    x = next;
    k1 = s.k;
    arc = nextArc;
    out.points.push_back(x);
    out.eigenvalues.push_back(s.sample.eigenvalues);
  }
}

}  // namespace tfd::core
