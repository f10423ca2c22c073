#include "core/topology/segment_classification.h"

#include <algorithm>
#include <cmath>

#include "core/topology/traceless5.h"

namespace tfd::core::topology {

PatternSample patternAt(const std::array<Mat3, 3>& g, const Vec3& e0) {
  PatternSample s;
  const double len = e0.norm();
  if (len == 0) return s;
  const Vec3 e = e0 / len;
  Vec3 u, w;
  completeFrame(e, u, w);
  Vec3 gradAlpha, gradBeta;
  for (int k = 0; k < 3; ++k) {
    const Vec3 gu = g[k] * u, gw = g[k] * w;
    gradAlpha[k] = 0.5 * (u.dot(gu) - w.dot(gw));
    gradBeta[k] = u.dot(gw);
  }
  const Vec3 t = gradAlpha.cross(gradBeta);
  const double tl = t.norm();
  if (tl == 0) return s;
  s.tangent = t / tl;
  s.cosine = std::clamp(s.tangent.dot(e), -1.0, 1.0);
  return s;
}

namespace {

/// Unit direction of travel along the arc at θ (towards increasing θ).
Vec3 travelDirection(const TetConic& conic, double theta, double step, const Vec3& fallback) {
  const ConicPoint a = conic.point(theta - step), b = conic.point(theta + step);
  if (!a.finite || !b.finite) return fallback;
  const Vec3 d = b.position - a.position;
  const double n = d.norm();
  return n > 0 ? Vec3(d / n) : fallback;
}

Vec3 orient(const Vec3& tangent, const Vec3& direction) {
  return tangent.dot(direction) < 0 ? Vec3(-tangent) : tangent;
}

}  // namespace

ArcClassification classifyArc(const TetConic& conic, double thetaStart, double thetaEnd,
                              const Vec3& eStart, const Vec3& eEnd, int extraSamples) {
  ArcClassification out;
  const std::array<Mat3, 3> g = conic.field().gradientMatrices();
  const double span = thetaEnd - thetaStart;
  const double step = 1e-4 * span;
  const ConicPoint pa = conic.point(thetaStart), pb = conic.point(thetaEnd);
  const Vec3 chord = pa.finite && pb.finite ? Vec3(pb.position - pa.position) : Vec3::Zero();
  const auto sampleAt = [&](double theta, const Vec3& e) {
    PatternSample s = patternAt(g, e);
    s.tangent = orient(s.tangent, travelDirection(conic, theta, step, chord));
    return s;
  };
  out.start = sampleAt(thetaStart + step, eStart);
  out.start = PatternSample{patternAt(g, eStart).cosine, out.start.tangent};
  out.end = sampleAt(thetaEnd - step, eEnd);
  out.end = PatternSample{patternAt(g, eEnd).cosine, out.end.tangent};

  const auto cosineAt = [&](double theta) {
    const ConicPoint p = conic.point(theta);
    return patternAt(g, p.eigenvector).cosine;
  };
  const auto makePoint = [&](double theta, bool transition) {
    ArcPoint a;
    const ConicPoint p = conic.point(theta);
    a.theta = theta;
    a.position = p.position;
    a.eigenvector = p.eigenvector;
    const PatternSample s = patternAt(g, p.eigenvector);
    a.cosine = transition ? 0 : s.cosine;
    a.tangent = orient(s.tangent, travelDirection(conic, theta, step, chord));
    a.transition = transition;
    return a;
  };

  // Sign changes of δ on a fine sampling of the arc, then bisection.
  constexpr int kIntervals = 8;
  double previousTheta = thetaStart, previous = out.start.cosine;
  for (int i = 1; i <= kIntervals; ++i) {
    const double theta = i == kIntervals ? thetaEnd : thetaStart + span * i / kIntervals;
    const double current = i == kIntervals ? out.end.cosine : cosineAt(theta);
    if ((previous > 0 && current < 0) || (previous < 0 && current > 0)) {
      double lo = previousTheta, hi = theta, flo = previous;
      for (int it = 0; it < 60 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        const double fm = cosineAt(mid);
        if ((fm > 0) == (flo > 0) && fm != 0)
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      out.interior.push_back(makePoint(0.5 * (lo + hi), true));
    }
    previousTheta = theta, previous = current;
  }
  for (int i = 1; i <= extraSamples; ++i) {
    out.interior.push_back(makePoint(thetaStart + span * i / (extraSamples + 1), false));
  }
  std::sort(out.interior.begin(), out.interior.end(),
            [](const ArcPoint& a, const ArcPoint& b) { return a.theta < b.theta; });
  return out;
}

ArcClassification classifyChord(const TetLinearField& field, const Vec3& a, const Vec3& b,
                                const Vec3& eStart, const Vec3& eEnd) {
  ArcClassification out;
  const std::array<Mat3, 3> g = field.gradientMatrices();
  Vec3 chord = b - a;
  if (chord.norm() > 0) chord.normalize();
  out.start = patternAt(g, eStart);
  out.end = patternAt(g, eEnd);
  out.start.tangent = out.start.tangent.norm() > 0 ? orient(out.start.tangent, chord) : chord;
  out.end.tangent = out.end.tangent.norm() > 0 ? orient(out.end.tangent, chord) : chord;
  const double c0 = out.start.cosine, c1 = out.end.cosine;
  if ((c0 > 0 && c1 < 0) || (c0 < 0 && c1 > 0)) {
    const double s = c0 / (c0 - c1);
    ArcPoint p;
    p.position = a + s * (b - a);
    p.eigenvector = ((1 - s) * eStart + s * (eStart.dot(eEnd) < 0 ? -eEnd : eEnd)).normalized();
    p.tangent = chord;
    p.transition = true;
    out.interior.push_back(p);
  }
  return out;
}

}  // namespace tfd::core::topology
