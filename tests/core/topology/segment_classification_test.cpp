// Wedge / trisector classification (core/topology/segment_classification.h, paper §3): against
// the designed pattern of a degenerate element (Eq. 3) and an independent winding number of the
// projected field around the curve; transition points on conic arcs where the curve's tangent
// (by finite differences of the conic) is perpendicular to the eigenvector; the chord fallback.
#include "core/topology/segment_classification.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/design/design_element.h"
#include "tests/core/topology/tet_field_checks.h"

namespace tfd::core::topology {
namespace {

using testing::randomTet;
using testing::relativeGap;
using testing::TetData;

constexpr double kPi = std::numbers::pi;

std::array<Mat3, 3> gradientsOf(const LocalLinearization& l) {
  const Tensor a0 = l.evaluate(l.origin);
  std::array<Mat3, 3> g;
  for (int k = 0; k < 3; ++k) g[k] = (l.evaluate(l.origin + Vec3::Unit(k)) - a0).matrix();
  return g;
}

/// Winding number of (α, β) = (½(uᵀAu − wᵀAw), uᵀAw) around a small loop about the origin in
/// the plane (u, w), run counter-clockwise seen from e = u × w: +1 for a wedge, −1 for a
/// trisector (the eigenvectors turn by ±½ turn).
int winding(const LocalLinearization& l, const Vec3& u, const Vec3& w) {
  const int steps = 720;
  double total = 0, previous = 0;
  for (int i = 0; i <= steps; ++i) {
    const double phi = 2 * kPi * i / steps;
    const Mat3 a = l.evaluate(l.origin + 1e-3 * (std::cos(phi) * u + std::sin(phi) * w)).matrix();
    const double angle = std::atan2(u.dot(a * w), 0.5 * (u.dot(a * u) - w.dot(a * w)));
    if (i > 0) total += std::remainder(angle - previous, 2 * kPi);
    previous = angle;
  }
  return static_cast<int>(std::lround(total / (2 * kPi)));
}

TEST(SegmentClassification, DesignedWedgesAndTrisectorsAreRecognised) {
  int cases = 0;
  for (const auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
    for (const auto pattern : {DegeneratePattern::Wedge, DegeneratePattern::Trisector}) {
      for (const Vec3& euler : {Vec3(0, 0, 0), Vec3(30, -40, 75), Vec3(170, 20, -5)}) {
        const Mat3 frame = rotationFromEulerDegrees(euler);
        const LocalLinearization l =
            makeDegenerateLinearization(Vec3(0.3, -0.2, 0.1), frame, type, pattern);
        const Vec3 e = frame.col(2);
        const PatternSample s = patternAt(gradientsOf(l), e);
        const int w = winding(l, frame.col(0), frame.col(1));
        const bool wedge = pattern == DegeneratePattern::Wedge;
        EXPECT_EQ(w, wedge ? 1 : -1) << "independent check of the designed pattern";
        EXPECT_EQ(s.cosine > 0, wedge);
        EXPECT_GT(std::abs(s.cosine), 0.5) << "the designed curve runs along e";
        // Neither the sign of e nor the scale of the field matters.
        EXPECT_NEAR(patternAt(gradientsOf(l), -e).cosine, s.cosine, 1e-14);
        auto g = gradientsOf(l);
        for (auto& m : g) m *= 3.5;
        EXPECT_NEAR(patternAt(g, e).cosine, s.cosine, 1e-14);
        // The tangent is the curve's direction: the field stays degenerate to second order along
        // it, not across it.
        const Vec3 across = s.tangent.cross(e).norm() > 0.1 ? Vec3(s.tangent.cross(e).normalized())
                                                            : Vec3(s.tangent.unitOrthogonal());
        const double along = relativeGap(l.evaluate(l.origin + 1e-4 * s.tangent));
        const double off = relativeGap(l.evaluate(l.origin + 1e-4 * across));
        EXPECT_LT(along, 1e-3 * off);
        ++cases;
      }
    }
  }
  EXPECT_EQ(cases, 12);
}

TEST(SegmentClassification, TransitionPointsAreWhereTheTangentIsPerpendicularToE) {
  int transitions = 0, arcs = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const TetData t = randomTet(rng);
    const TetLinearField field(t.corners, t.tensors);
    const TetConic conic(field);
    ASSERT_TRUE(conic.valid());
    for (double start = -kPi; start < kPi - 0.1; start += 0.7) {
      const double end = start + 0.6;
      // Only arcs that stay at a finite, moderate distance.
      bool ok = true;
      for (int i = 0; i <= 60 && ok; ++i) {
        const ConicPoint p = conic.point(start + 0.6 * i / 60);
        ok = p.finite && p.position.norm() < 20;
      }
      if (!ok) continue;
      ++arcs;
      const ArcClassification arc = classifyArc(conic, start, end, conic.point(start).eigenvector,
                                                conic.point(end).eigenvector, 3);
      // Independent: the sign changes of t·e with t the finite-difference tangent of the conic
      // and e kept continuous along the arc.
      int fdChanges = 0;
      double previous = 0;
      Vec3 ePrev = conic.point(start).eigenvector;
      for (int i = 0; i <= 2000; ++i) {
        const double th = start + 0.6 * i / 2000;
        const Vec3 tfd = (conic.point(th + 1e-6).position - conic.point(th - 1e-6).position);
        Vec3 e = conic.point(th).eigenvector;
        if (e.dot(ePrev) < 0) e = -e;
        ePrev = e;
        const double c = tfd.normalized().dot(e);
        if (i > 0 && ((c > 0) != (previous > 0))) ++fdChanges;
        previous = c;
      }
      int reported = 0, extra = 0;
      double lastTheta = start;
      for (const ArcPoint& p : arc.interior) {
        EXPECT_GT(p.theta, lastTheta);
        EXPECT_LT(p.theta, end);
        lastTheta = p.theta;
        EXPECT_LT((p.position - conic.point(p.theta).position).norm(), 1e-12);
        if (!p.transition) {
          ++extra;
          continue;
        }
        ++reported;
        const Vec3 tfd =
            (conic.point(p.theta + 1e-6).position - conic.point(p.theta - 1e-6).position)
                .normalized();
        EXPECT_LT(std::abs(tfd.dot(p.eigenvector)), 1e-5) << "seed " << seed;
        EXPECT_EQ(p.cosine, 0);
      }
      EXPECT_EQ(extra, 3);
      EXPECT_EQ(reported, fdChanges) << "seed " << seed << " arc at " << start;
      EXPECT_EQ(reported % 2 == 1, (arc.start.cosine > 0) != (arc.end.cosine > 0));
      transitions += reported;
    }
  }
  EXPECT_GT(arcs, 100);
  EXPECT_GT(transitions, 5) << "the check is not vacuous";
}

TEST(SegmentClassification, ChordPutsTheTransitionWhereDeltaInterpolatesToZero) {
  // Two end points with opposite patterns: a wedge element and a trisector element's gradients
  // are not one field, so build one field and pick end eigenvectors of opposite sign of δ.
  std::mt19937_64 rng(3);
  const TetData t = randomTet(rng);
  const TetLinearField field(t.corners, t.tensors);
  const auto g = field.gradientMatrices();
  Vec3 eWedge = Vec3::Zero(), eTri = Vec3::Zero();
  for (int i = 0; i < 200 && (eWedge.isZero() || eTri.isZero()); ++i) {
    const Vec3 e = Vec3(std::cos(i * 0.37), std::sin(i * 0.37), std::cos(i * 0.11)).normalized();
    const double c = patternAt(g, e).cosine;
    if (c > 0.2 && eWedge.isZero()) eWedge = e;
    if (c < -0.2 && eTri.isZero()) eTri = e;
  }
  ASSERT_FALSE(eWedge.isZero() || eTri.isZero());
  const Vec3 a(0.1, 0.1, 0.1), b(0.6, 0.3, 0.2);
  const ArcClassification arc = classifyChord(field, a, b, eWedge, eTri);
  ASSERT_EQ(arc.interior.size(), 1u);
  const double c0 = patternAt(g, eWedge).cosine, c1 = patternAt(g, eTri).cosine;
  const double s = c0 / (c0 - c1);
  EXPECT_LT((arc.interior[0].position - (a + s * (b - a))).norm(), 1e-14);
  EXPECT_TRUE(arc.interior[0].transition);
  EXPECT_GT(arc.start.cosine, 0);
  EXPECT_LT(arc.end.cosine, 0);
  EXPECT_GT(arc.start.tangent.dot(b - a), 0) << "tangents oriented from start to end";
  EXPECT_GT(arc.end.tangent.dot(b - a), 0);
  // Same pattern at both ends: no transition.
  EXPECT_TRUE(classifyChord(field, a, b, eWedge, eWedge).interior.empty());
}

}  // namespace
}  // namespace tfd::core::topology
