// Spline through control points and its even arc-length sampling (core/design/spline.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/design/spline.h"
#include "core/error.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> wigglyPoints() {
  return {{0, 0, 0}, {1, 0.2, 0}, {1.5, 1, 0.3}, {1.2, 2, 0.9}, {0.3, 2.4, 1.0}, {-0.5, 2.0, 2.0}};
}

std::vector<Vec3> circlePoints(int n, double r) {
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    p.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  return p;
}

/// Length of the spline by brute force: many chords.
double chordLength(const Spline& s, int perSegment = 20000) {
  double total = 0;
  const int steps = perSegment * s.segmentCount();
  Vec3 prev = s.position(0);
  for (int k = 1; k <= steps; ++k) {
    const Vec3 p = s.position(double(k) / perSegment);
    total += (p - prev).norm();
    prev = p;
  }
  return total;
}

TEST(CurveSpline, InterpolatesEveryControlPoint) {
  for (bool closed : {false, true}) {
    const auto pts = wigglyPoints();
    const Spline s(pts, closed);
    ASSERT_EQ(s.segmentCount(), closed ? 6 : 5);
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
      EXPECT_LT((s.position(i) - pts[i]).norm(), 1e-14) << i;
    }
    if (closed) {
      EXPECT_LT((s.position(6) - pts[0]).norm(), 1e-14);
    }
  }
}

TEST(CurveSpline, TwoPointsGiveAStraightSegmentAtConstantSpeed) {
  const Vec3 a(0.1, -0.2, 0.3), b(1.1, 0.8, -0.7);
  const Spline s({a, b}, false);
  for (double u : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    EXPECT_LT((s.position(u) - (a + u * (b - a))).norm(), 1e-15);
  }
  EXPECT_NEAR(s.length(), (b - a).norm(), 1e-14);
  const CurveSamples c = s.sample(0.1);
  ASSERT_EQ(c.positions.size(), 18u);  // |b − a| = 1.732: 17 intervals
  for (std::size_t i = 0; i < c.positions.size(); ++i) {
    EXPECT_LT((c.positions[i] - (a + (b - a) * (double(i) / 17))).norm(), 1e-13);
    EXPECT_LT((c.tangents[i] - (b - a).normalized()).norm(), 1e-14);
  }
}

TEST(CurveSpline, TangentDirectionIsContinuousAcrossControlPoints) {
  for (bool closed : {false, true}) {
    const Spline s(wigglyPoints(), closed);
    const int last = closed ? s.segmentCount() : s.segmentCount() - 1;
    for (int i = 1; i <= last; ++i) {
      const Vec3 left = s.derivative(i - 1e-13).normalized();
      const Vec3 right = s.derivative(closed ? (i % s.segmentCount()) : i).normalized();
      EXPECT_LT((left - right).norm(), 1e-9) << "control point " << i;
    }
  }
}

TEST(CurveSpline, ArcLengthMatchesBruteForceAndInverts) {
  for (bool closed : {false, true}) {
    const Spline s(wigglyPoints(), closed);
    EXPECT_NEAR(s.length(), chordLength(s), 1e-8 * s.length());
    for (double u : {0.3, 1.0, 2.71, 4.5}) {
      const double len = s.arcLengthAt(u);
      EXPECT_NEAR(s.parameterAt(len), u, 1e-10);
    }
    for (double f : {0.0, 0.123, 0.5, 0.999}) {
      EXPECT_NEAR(s.arcLengthAt(s.parameterAt(f * s.length())), f * s.length(), 1e-11);
    }
  }
}

TEST(CurveSpline, SamplesAreEvenlySpacedInArcLengthAndIncludeBothEnds) {
  const auto pts = wigglyPoints();
  const Spline s(pts, false);
  const CurveSamples c = s.sample(0.13);
  const int intervals = static_cast<int>(std::round(s.length() / 0.13));
  ASSERT_EQ(c.positions.size(), std::size_t(intervals + 1));
  EXPECT_NEAR(c.spacing, s.length() / intervals, 1e-15);
  EXPECT_EQ(c.positions.front(), pts.front());
  EXPECT_EQ(c.positions.back(), pts.back());
  for (std::size_t i = 0; i < c.positions.size(); ++i) {
    EXPECT_NEAR(c.arcLength[i], i * c.spacing, 1e-12);
    // Independent check: the arc between consecutive samples, measured by many small chords.
    if (i + 1 < c.positions.size()) {
      const double u0 = s.parameterAt(c.arcLength[i]), u1 = s.parameterAt(c.arcLength[i + 1]);
      double arc = 0;
      Vec3 prev = s.position(u0);
      for (int k = 1; k <= 4000; ++k) {
        const Vec3 p = s.position(u0 + (u1 - u0) * k / 4000);
        arc += (p - prev).norm();
        prev = p;
      }
      EXPECT_NEAR(arc, c.spacing, 1e-6 * c.spacing);
      EXPECT_LE((c.positions[i + 1] - c.positions[i]).norm(), c.spacing + 1e-12);
    }
    EXPECT_NEAR(c.tangents[i].norm(), 1.0, 1e-14);
    // The tangent is the direction of motion (finite difference of the spline).
    const double u = s.parameterAt(c.arcLength[i]);
    const double h = 1e-6;
    const double a = std::max(0.0, u - h), b = std::min(double(s.segmentCount()), u + h);
    EXPECT_LT((c.tangents[i] - (s.position(b) - s.position(a)).normalized()).norm(), 1e-6);
  }
}

TEST(CurveSpline, ClosedCircleIsRoundAndPeriodic) {
  const double r = 0.7;
  const Spline s(circlePoints(12, r), true);
  EXPECT_NEAR(s.length(), 2 * kPi * r, 2e-3 * 2 * kPi * r);
  for (int k = 0; k < 600; ++k) {
    const Vec3 p = s.position(12.0 * k / 600);
    EXPECT_NEAR(p.norm(), r, 3e-3 * r);
    EXPECT_EQ(p.z(), 0);
  }
  const CurveSamples c = s.sample(0.1);
  const int intervals = static_cast<int>(std::round(s.length() / 0.1));
  ASSERT_EQ(c.positions.size(), std::size_t(intervals));  // the start is not repeated
  ASSERT_EQ(c.arcLength.size(), c.positions.size() + 1);
  EXPECT_NEAR(c.arcLength.back(), s.length(), 1e-15);
  // The closing step is as long as the others.
  EXPECT_NEAR((c.positions.back() - c.positions.front()).norm(),
              (c.positions[1] - c.positions[0]).norm(), 1e-6);
}

TEST(CurveSpline, ClosedCurveDropsARepeatedFirstPoint) {
  auto pts = circlePoints(5, 1);
  pts.push_back(pts.front());
  const Spline s(pts, true);
  EXPECT_EQ(s.controlPoints().size(), 5u);
  EXPECT_EQ(s.segmentCount(), 5);
}

TEST(CurveSpline, ShortCurvesStillGetTheirEnds) {
  const Spline open({{0, 0, 0}, {0.05, 0, 0}}, false);
  const CurveSamples a = open.sample(1.0);
  ASSERT_EQ(a.positions.size(), 2u);
  EXPECT_EQ(a.positions[1], Vec3(0.05, 0, 0));
  const Spline closed(circlePoints(3, 0.01), true);
  EXPECT_EQ(closed.sample(1.0).positions.size(), 3u);  // at least three samples on a loop
}

TEST(CurveSpline, RefusesBadInput) {
  const auto throwsWith = [](auto&& fn, const std::string& text) {
    try {
      fn();
      ADD_FAILURE() << "no error, expected: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  throwsWith([] { Spline({{0, 0, 0}}, false); }, "at least two control points");
  throwsWith([] { Spline({}, false); }, "at least two control points");
  throwsWith([] { Spline({{0, 0, 0}, {1, 0, 0}}, true); }, "at least three distinct");
  throwsWith(
      [] {
        Spline({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}, false);
      },
      "control points 1 and 2 coincide");
  throwsWith([] { Spline({{0, 0, 0}, {NAN, 0, 0}}, false); }, "control point 1");
  const Spline s({{0, 0, 0}, {1, 0, 0}}, false);
  throwsWith([&] { s.sample(0); }, "spacing must be a positive number");
  throwsWith([&] { s.sample(-1); }, "spacing must be a positive number");
  throwsWith([&] { s.sample(NAN); }, "spacing must be a positive number");
  throwsWith([&] { s.sample(1e-9); }, "samples");
  // A hairpin (P0, P1, P0) makes the tangent vanish at P1.
  throwsWith([] { Spline({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, false).sample(0.5); }, "doubles back");
}

}  // namespace
}  // namespace tfd::core
