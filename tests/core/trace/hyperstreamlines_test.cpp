// Hyperstreamlines (core/trace/hyperstreamlines.h) on analytic fields with known eigenvectors
// and a known degenerate line: tangent to the eigenvector, never closer than the test
// distance, ending at the degenerate line and the boundary, the same for any thread count.
#include "core/trace/hyperstreamlines.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "tests/core/trace/trace_test_support.h"

namespace tfd::core {
namespace {

using test::exactEigenvector;
using test::sampleField;

constexpr double kDegree = std::numbers::pi / 180;

/// F1 in a box off the z axis: r ≥ 0.2, so no degenerate point; curved medium lines.
TensorField offAxisF1() {
  return sampleField(makeBoxMesh(10, 12, 4, Vec3(0.2, -0.6, -0.2), Vec3(1.2, 0.6, 0.2)), test::f1);
}

/// The largest angle between a segment and the exact eigenvector at its midpoint.
double worstTangentAngle(const Polylines& lines, const test::FieldFunction& f, int column) {
  double worst = 0;
  for (const Polyline& l : lines.lines)
    for (std::size_t i = 0; i + 1 < l.points.size(); ++i) {
      const Vec3 chord = (l.points[i + 1] - l.points[i]).normalized();
      const Vec3 e = exactEigenvector(f(0.5 * (l.points[i] + l.points[i + 1])), column);
      worst = std::max(worst, std::acos(std::min(1.0, std::abs(chord.dot(e)))));
    }
  return worst;
}

/// Smallest distance between points of different lines (brute force).
double closestApproach(const Polylines& lines) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < lines.lines.size(); ++a)
    for (std::size_t b = a + 1; b < lines.lines.size(); ++b)
      for (const Vec3& p : lines.lines[a].points)
        for (const Vec3& q : lines.lines[b].points) best = std::min(best, (p - q).norm());
  return best;
}

TEST(Hyperstreamlines, CurvedMediumLinesOfF1AreTangentToTheEigenvectorWithinADegree) {
  const TensorField field = offAxisF1();
  HyperstreamlineOptions o;
  o.family = EigenFamily::Medium;
  o.separation = 0.1;
  const Polylines lines = traceHyperstreamlines(field, o);
  ASSERT_GT(lines.lines.size(), 20u) << lines.summary();
  ASSERT_GT(lines.pointCount(), 1000u);
  EXPECT_LT(worstTangentAngle(lines, test::f1, 1), 1 * kDegree) << lines.summary();
  // The lines really curve (the medium eigenvector turns by θ/2).
  double turn = 0;
  for (const Polyline& l : lines.lines)
    turn =
        std::max(turn, std::acos(std::clamp(
                           (l.points[1] - l.points[0])
                               .normalized()
                               .dot((l.points.back() - l.points[l.points.size() - 2]).normalized()),
                           -1.0, 1.0)));
  EXPECT_GT(turn, 10 * kDegree);
}

TEST(Hyperstreamlines, RandomLinearFieldsEveryFamilyTangentWithinADegree) {
  for (unsigned seed : {3u, 11u}) {
    const auto f = test::randomLinearField(seed);
    const TensorField field =
        sampleField(makeBoxMesh(6, 6, 6, Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)), f);
    for (EigenFamily family : {EigenFamily::Major, EigenFamily::Medium, EigenFamily::Minor}) {
      SCOPED_TRACE(std::string(toString(family)) + " seed " + std::to_string(seed));
      HyperstreamlineOptions o;
      o.family = family;
      o.separation = 0.12;
      const Polylines lines = traceHyperstreamlines(field, o);
      ASSERT_GT(lines.lines.size(), 5u) << lines.summary();
      EXPECT_LT(worstTangentAngle(lines, f, static_cast<int>(family)), 1 * kDegree);
    }
  }
}

TEST(Hyperstreamlines, PointsOfDifferentLinesNeverComeCloserThanTheTestDistance) {
  const TensorField field = offAxisF1();
  for (double ratio : {0.5, 1.0}) {
    SCOPED_TRACE("test ratio " + std::to_string(ratio));
    HyperstreamlineOptions o;
    o.family = EigenFamily::Medium;
    o.separation = 0.1;
    o.testRatio = ratio;
    const Polylines lines = traceHyperstreamlines(field, o);
    ASSERT_GT(lines.lines.size(), 10u);
    EXPECT_GE(closestApproach(lines), ratio * o.separation * (1 - 1e-12));
    // And they fill the box: no inner point is farther than 2 separations from a line.
    const Vec3 lo(0.25, -0.55, -0.15), hi(1.15, 0.55, 0.15);
    double gap = 0;
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j)
        for (int k = 0; k <= 2; ++k) {
          const Vec3 p = lo + (hi - lo).cwiseProduct(Vec3(i / 8.0, j / 8.0, k / 2.0));
          double nearest = std::numeric_limits<double>::infinity();
          for (const Polyline& l : lines.lines)
            for (const Vec3& q : l.points) nearest = std::min(nearest, (p - q).norm());
          gap = std::max(gap, nearest);
        }
    EXPECT_LT(gap, 2 * o.separation);
  }
}

TEST(Hyperstreamlines, LinesEndAtTheDegenerateLineOfF1AndAtTheBoundary) {
  // The medium eigenvector of F1 points at the z axis along the positive x axis (θ = 0).
  const TensorField field =
      sampleField(makeBoxMesh(8, 8, 4, Vec3(-1, -1, -0.3), Vec3(1, 1, 0.3)), test::f1);
  HyperstreamlineOptions o;
  o.family = EigenFamily::Medium;
  o.separation = 0.1;
  o.seeds = {Vec3(0.5, 0, 0.05)};
  o.automaticSeeds = false;
  const Polylines one = traceHyperstreamlines(field, o);
  ASSERT_EQ(one.lines.size(), 1u);
  const Polyline& l = one.lines[0];
  // One end on the axis (gap 2r/‖A‖ < min_gap: r ≈ 0.012), the other at x = 1.
  const Vec3 toAxis = l.stops[0] == LineStop::Degenerate ? l.points.front() : l.points.back();
  const Vec3 toWall = l.stops[0] == LineStop::Degenerate ? l.points.back() : l.points.front();
  EXPECT_TRUE(l.stops[0] == LineStop::Degenerate || l.stops[1] == LineStop::Degenerate);
  EXPECT_TRUE(l.stops[0] == LineStop::Boundary || l.stops[1] == LineStop::Boundary);
  EXPECT_LT(std::hypot(toAxis.x(), toAxis.y()), 0.03);
  EXPECT_GT(toAxis.x(), 0);
  EXPECT_GT(toWall.x(), 1 - hyperstreamlineStep(field, o) / 16);

  // Filling the whole box: every line that ends at a degeneracy ends next to the axis, and no
  // line crosses it.
  o.seeds.clear();
  o.automaticSeeds = true;
  const Polylines all = traceHyperstreamlines(field, o);
  int degenerateEnds = 0;
  for (const Polyline& line : all.lines) {
    for (int end = 0; end < 2; ++end) {
      if (line.stops[end] != LineStop::Degenerate) continue;
      ++degenerateEnds;
      const Vec3& p = end == 0 ? line.points.front() : line.points.back();
      EXPECT_LT(std::hypot(p.x(), p.y()), 0.05) << p.transpose();
    }
    for (const Vec3& p : line.points) EXPECT_GT(std::hypot(p.x(), p.y()), 0.012);
  }
  EXPECT_GE(degenerateEnds, 1) << all.summary();
}

TEST(Hyperstreamlines, StraightMajorLinesReachTheBoundaryOrTheirMaximumLength) {
  // The major eigenvector of F1 is z everywhere: straight lines from wall to wall.
  const TensorField field =
      sampleField(makeBoxMesh(4, 4, 6, Vec3(0.5, -0.5, -0.3), Vec3(1.5, 0.5, 0.3)), test::f1);
  HyperstreamlineOptions o;
  o.separation = 0.2;
  const double step = hyperstreamlineStep(field, o);
  const Polylines lines = traceHyperstreamlines(field, o);
  ASSERT_GT(lines.lines.size(), 10u);
  for (const Polyline& l : lines.lines) {
    EXPECT_EQ(l.stops[0], LineStop::Boundary);
    EXPECT_EQ(l.stops[1], LineStop::Boundary);
    EXPECT_GT(std::abs(l.points.front().z()), 0.3 - step / 16);
    EXPECT_GT(std::abs(l.points.back().z()), 0.3 - step / 16);
    for (const Vec3& p : l.points) EXPECT_NEAR(p.x(), l.points[0].x(), 1e-12);
  }
  o.maxLength = 0.3;
  for (const Polyline& l : traceHyperstreamlines(field, o).lines) {
    EXPECT_LE(l.length(), 0.3 + 1e-12);
    EXPECT_TRUE(l.stops[0] == LineStop::MaxLength || l.stops[1] == LineStop::MaxLength);
  }
}

TEST(Hyperstreamlines, GivenSeedsAreOnTheirLinesAndTooCloseSeedsAreSkipped) {
  const TensorField field = offAxisF1();
  HyperstreamlineOptions o;
  o.family = EigenFamily::Medium;
  o.separation = 0.1;
  o.automaticSeeds = false;
  o.seeds = {Vec3(0.5, 0, 0), Vec3(0.8, 0.2, 0.1), Vec3(0.5001, 0, 0), Vec3(5, 5, 5)};
  const Polylines lines = traceHyperstreamlines(field, o);
  ASSERT_EQ(lines.lines.size(), 2u) << "the third seed is on the first line, the last outside";
  for (int i = 0; i < 2; ++i) {
    const auto& p = lines.lines[i].points;
    EXPECT_NE(std::find(p.begin(), p.end(), o.seeds[i]), p.end());
  }
  // Eigenvalues are those of the exact tensor at each point.
  for (const Polyline& l : lines.lines)
    for (std::size_t i = 0; i < l.points.size(); i += 7) {
      const double r = std::hypot(l.points[i].x(), l.points[i].y());
      EXPECT_NEAR(l.eigenvalues[i][0], 2, 1e-9);
      EXPECT_NEAR(l.eigenvalues[i][1], -1 + r, 1e-9);
      EXPECT_NEAR(l.eigenvalues[i][2], -1 - r, 1e-9);
    }
}

TEST(Hyperstreamlines, OneAndTwoThreadsGiveBitwiseEqualLines) {
  const TensorField field =
      sampleField(makeBoxMesh(8, 8, 8, Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)),
                  test::randomLinearField(5));
  HyperstreamlineOptions o;
  o.separation = 0.08;
  const auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    return traceHyperstreamlines(field, o);
  };
  const Polylines a = run(1), b = run(2);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  ASSERT_GT(a.lines.size(), 10u);
  for (std::size_t i = 0; i < a.lines.size(); ++i) {
    ASSERT_EQ(a.lines[i].points, b.lines[i].points) << "line " << i;
    ASSERT_EQ(a.lines[i].eigenvalues, b.lines[i].eigenvalues) << "line " << i;
    ASSERT_EQ(a.lines[i].stops, b.lines[i].stops) << "line " << i;
  }
}

TEST(Hyperstreamlines, BadOptionsAreRefusedWithTheirName) {
  const TensorField field = offAxisF1();
  const auto refuses = [&](auto change, const char* word) {
    HyperstreamlineOptions o;
    change(o);
    try {
      traceHyperstreamlines(field, o);
      ADD_FAILURE() << "accepted bad " << word;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  refuses([](auto& o) { o.separation = 0; }, "separation");
  refuses([](auto& o) { o.separation = 1e-6; }, "separation");
  refuses([](auto& o) { o.testRatio = 1.5; }, "ratio");
  refuses([](auto& o) { o.step = -1; }, "step");
  refuses([](auto& o) { o.maxTurnDegrees = 0; }, "turn");
  refuses([](auto& o) { o.seeds = {Vec3(NAN, 0, 0)}; }, "seed 0");
}

}  // namespace
}  // namespace tfd::core
