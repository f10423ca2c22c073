// Curve element builder: control points + options -> CurveElement
// (core/design/curve_element_builder.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/design/curve_element_builder.h"
#include "core/design/parallel_transport.h"
#include "core/design/spline.h"
#include "core/error.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> openPoints() {
  return {{-0.6, -0.2, 0.0}, {-0.2, 0.1, 0.2}, {0.2, 0.0, -0.1}, {0.6, 0.3, 0.1}};
}
std::vector<Vec3> loopPoints() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) {
    const double s = 2 * kPi * i / 8;
    p.push_back({0.5 * std::cos(s), 0.5 * std::sin(s), 0.2 * std::sin(2 * s) + 0.1 * std::cos(s)});
  }
  return p;
}

/// Winding number of the major eigenvector of the 2-D projection of the linearisation onto the
/// plane spanned by (p, q), around `center`: +1/2 wedge, −1/2 trisector.
double winding(const LocalLinearization& l, const Vec3& center, const Vec3& p, const Vec3& q) {
  const int n = 720;
  double total = 0, previous = 0;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * kPi * k / n;
    const Mat3 t = l.evaluate(center + 1e-3 * (std::cos(a) * p + std::sin(a) * q)).matrix();
    const double mpp = p.dot(t * p), mqq = q.dot(t * q), mpq = p.dot(t * q);
    const double angle = 0.5 * std::atan2(2 * mpq, mpp - mqq);
    if (k > 0) {
      double d = angle - previous;
      while (d > kPi / 2) d -= kPi;
      while (d < -kPi / 2) d += kPi;
      total += d;
    }
    previous = angle;
  }
  return total / (2 * kPi);
}

TEST(CurveBuilder, SamplesFollowTheSplineWithTheTangentAsThirdFrameColumn) {
  CurveOptions o;
  o.points = openPoints();
  o.spacing = 0.04;
  o.radius = 0.12;
  CurveBuildReport report;
  const CurveElement c = buildCurveElement(o, &report);
  const CurveSamples s = Spline(o.points, false).sample(o.spacing);
  ASSERT_EQ(c.samples.size(), s.positions.size());
  EXPECT_EQ(report.samples, c.samples.size());
  EXPECT_NEAR(report.spacing, s.spacing, 1e-15);
  EXPECT_TRUE(c.degenerate);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.radius, 0.12);
  EXPECT_EQ(c.samples.front().origin, o.points.front());
  EXPECT_EQ(c.samples.back().origin, o.points.back());
  for (std::size_t i = 0; i < c.samples.size(); ++i) {
    const Mat3& f = c.samples[i].frame;
    EXPECT_LT((f.transpose() * f - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(f.determinant(), 1, 1e-12);
    EXPECT_LT((f.col(2) - s.tangents[i]).norm(), 1e-13);
    EXPECT_LT((c.samples[i].origin - s.positions[i]).norm(), 1e-15);
    // Twist-free: u of the next sample is the parallel transport of this one.
    if (i + 1 < c.samples.size()) {
      const Vec3 moved = transportRotation(f.col(2), c.samples[i + 1].frame.col(2)) * f.col(0);
      EXPECT_LT((moved - c.samples[i + 1].frame.col(0)).norm(), 1e-12);
    }
  }
}

TEST(CurveBuilder, DegenerateSamplesHaveTheTangentAsNonDegenerateEigenvector) {
  for (auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
    CurveOptions o;
    o.points = openPoints();
    o.type = type;
    const CurveElement c = buildCurveElement(o);
    for (const auto& s : c.samples) {
      const Tensor t = s.evaluate(s.origin);
      const EigenDecomposition e = eigenDecompose(t);
      if (type == DegenerateType::Linear) {
        EXPECT_NEAR(e.values[0], 2, 1e-12);
        EXPECT_NEAR(e.values[1], -1, 1e-12);
        EXPECT_NEAR(e.values[2], -1, 1e-12);
        EXPECT_NEAR(std::abs(e.vectors.col(0).dot(s.frame.col(2))), 1, 1e-12);
      } else {
        EXPECT_NEAR(e.values[0], 1, 1e-12);
        EXPECT_NEAR(e.values[1], 1, 1e-12);
        EXPECT_NEAR(e.values[2], -2, 1e-12);
        EXPECT_NEAR(std::abs(e.vectors.col(2).dot(s.frame.col(2))), 1, 1e-12);
      }
    }
  }
}

TEST(CurveBuilder, PatternsWindByPlusOrMinusOneHalf) {
  for (auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
    for (auto pattern : {DegeneratePattern::Wedge, DegeneratePattern::Trisector}) {
      for (const Vec3& rotation : {Vec3(0, 0, 0), Vec3(25, -10, 40)}) {
        CurveOptions o;
        o.points = loopPoints();
        o.closed = true;
        o.type = type;
        o.pattern = pattern;
        o.rotation = rotation;
        const CurveElement c = buildCurveElement(o);
        const double expected = pattern == DegeneratePattern::Wedge ? 0.5 : -0.5;
        for (std::size_t i = 0; i < c.samples.size(); i += 7) {
          const auto& s = c.samples[i];
          EXPECT_NEAR(winding(s, s.origin, s.frame.col(0), s.frame.col(1)), expected, 1e-9);
        }
      }
    }
  }
}

TEST(CurveBuilder, CustomPatternBlocksReplaceTheJacobian) {
  PatternBlocks b;
  b.tx << 0.5, 0.2, 0.2, -0.5;
  b.ty << -0.3, -1.0, -1.0, 0.3;
  const double delta = patternDelta(b);  // 0.5·(−1) − (−0.3)·0.2 < 0: trisector
  ASSERT_LT(delta, 0);
  CurveOptions o;
  o.points = openPoints();
  o.customPattern = b;
  const CurveElement c = buildCurveElement(o);
  const double k = 1 / o.radius;  // canonical tube coordinates: per tube radius
  for (const auto& s : c.samples) {
    EXPECT_LT((s.jacobian[0] - Tensor{0.5, -0.5, 0, 0.2, 0, 0} * k).norm(), 1e-14);
    EXPECT_LT((s.jacobian[1] - Tensor{-0.3, 0.3, 0, -1.0, 0, 0} * k).norm(), 1e-14);
    EXPECT_EQ(s.jacobian[2], Tensor{});
    EXPECT_NEAR(winding(s, s.origin, s.frame.col(0), s.frame.col(1)), -0.5, 1e-9);
  }
  EXPECT_GT(patternDelta(defaultPatternBlocks(DegeneratePattern::Wedge)), 0);
  EXPECT_LT(patternDelta(defaultPatternBlocks(DegeneratePattern::Trisector)), 0);
}

TEST(CurveBuilder, UserRotationTiltsTheEigenvectorByAFixedAngle) {
  for (double degrees : {30.0, 90.0}) {
    CurveOptions o;
    o.points = openPoints();
    o.rotation = Vec3(degrees, 0, 0);
    const CurveElement c = buildCurveElement(o);
    for (const auto& s : c.samples) {
      const Vec3 e = eigenDecompose(s.evaluate(s.origin)).vectors.col(0);
      // The tangent is the third column of the unrotated frame: frame·Rᵀ.
      const Vec3 tangent = (s.frame * rotationFromEulerDegrees(o.rotation).transpose()).col(2);
      EXPECT_NEAR(std::acos(std::min(1.0, std::abs(e.dot(tangent)))) * 180 / kPi, degrees, 1e-6);
    }
  }
}

TEST(CurveBuilder, TensorKindPutsTheEigenvaluesOnTheFrame) {
  CurveOptions o;
  o.points = openPoints();
  o.kind = CurveKind::Tensor;
  o.eigenvalues = Vec3(0.5, -2, 1.5);  // along u, v, t
  const CurveElement c = buildCurveElement(o);
  EXPECT_FALSE(c.degenerate);
  for (const auto& s : c.samples) {
    const Tensor t = s.evaluate(s.origin + Vec3(0.01, 0.02, -0.01));  // constant per sample
    const EigenDecomposition e = eigenDecompose(t);
    EXPECT_NEAR(e.values[0], 1.5, 1e-12);
    EXPECT_NEAR(e.values[1], 0.5, 1e-12);
    EXPECT_NEAR(e.values[2], -2, 1e-12);
    EXPECT_NEAR(std::abs(e.vectors.col(0).dot(s.frame.col(2))), 1, 1e-12);  // tangent: major
    EXPECT_NEAR(std::abs(e.vectors.col(1).dot(s.frame.col(0))), 1, 1e-12);
  }
}

TEST(CurveBuilder, ClosedLoopFramesArePeriodic) {
  CurveOptions o;
  o.points = loopPoints();
  o.closed = true;
  o.spacing = 0.02;
  CurveBuildReport report;
  const CurveElement c = buildCurveElement(o, &report);
  EXPECT_TRUE(c.closed);
  EXPECT_GT(std::abs(report.holonomyDegrees), 1.0);  // something had to be spread
  // The step from the last sample back to the first twists like every other step, so the
  // frame field has no seam.
  const std::size_t n = c.samples.size();
  double firstTwist = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Mat3 &a = c.samples[i].frame, &b = c.samples[(i + 1) % n].frame;
    const Vec3 moved = transportRotation(a.col(2), b.col(2)) * a.col(0);
    const double twist = signedAngle(moved, b.col(0), b.col(2));
    if (i == 0) firstTwist = twist;
    EXPECT_NEAR(twist, firstTwist, 1e-10) << i;
  }
  EXPECT_NEAR(firstTwist * n, -report.holonomyDegrees * kPi / 180, 1e-9);
}

TEST(CurveBuilder, DesignIsIndependentOfTheModelUnits) {
  // The same design on a model scaled by 1000 gives the same tensor at corresponding points:
  // the Jacobian is per tube radius (canonical tube coordinates).
  CurveOptions o;
  o.points = openPoints();
  o.pattern = DegeneratePattern::Trisector;
  o.radius = 0.2;
  CurveOptions big = o;
  for (Vec3& p : big.points) p *= 1000;
  big.spacing *= 1000;
  big.radius *= 1000;
  const CurveElement a = buildCurveElement(o), b = buildCurveElement(big);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); i += 5) {
    const Vec3 offset(0.03, -0.05, 0.02);
    const Tensor ta = a.samples[i].evaluate(a.samples[i].origin + offset);
    const Tensor tb = b.samples[i].evaluate(b.samples[i].origin + 1000 * offset);
    EXPECT_LT((ta - tb).norm(), 1e-9);
    // At the tube's surface the pattern term has the size of the 2x2 blocks (|Tx| = √2).
    const Tensor surface =
        a.samples[i].evaluate(a.samples[i].origin + o.radius * a.samples[i].frame.col(0));
    EXPECT_NEAR((surface - a.samples[i].evaluate(a.samples[i].origin)).norm(), std::sqrt(2.0),
                1e-12);
  }
}

TEST(CurveBuilder, RefusesBadInputNamingTheParameter) {
  const auto expectError = [](CurveOptions o, const std::string& text) {
    try {
      buildCurveElement(o);
      ADD_FAILURE() << "no error, expected: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  CurveOptions o;
  o.points = openPoints();
  CurveOptions a = o;
  a.points.resize(1);
  expectError(a, "points: needs at least two control points");
  CurveOptions b = o;
  b.points.resize(2);
  b.closed = true;
  expectError(b, "points: a closed curve needs at least three");
  CurveOptions c = o;
  c.spacing = 0;
  expectError(c, "spacing: must be a positive number");
  c.spacing = -0.1;
  expectError(c, "spacing: must be a positive number");
  CurveOptions d = o;
  d.radius = 0;
  expectError(d, "radius: must be a positive number");
  CurveOptions e = o;
  e.customPattern = PatternBlocks{};
  e.customPattern->tx << 1, 0, 0, -1;
  e.customPattern->ty << 1, 0, 0, -1;  // parallel to Tx: δ = 0
  expectError(e, "neither a wedge nor a trisector");
  e.customPattern->ty << 0, 1, 0.5, 0;
  expectError(e, "must be symmetric");
  CurveOptions f = o;
  f.points[2] = f.points[1];
  expectError(f, "points: control points 1 and 2 coincide");
  CurveOptions g = o;
  g.pattern = DegeneratePattern::Transition;
  EXPECT_THROW(buildCurveElement(g), Error);
}

}  // namespace
}  // namespace tfd::core
