// Curve constraints: the tube around a curve and its fixed values
// (core/design/curve_constraint.h, core/region/curve_tube.h).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <set>

#include "core/design/curve_constraint.h"
#include "core/design/curve_element_builder.h"
#include "core/design/fixed_values.h"
#include "core/error.h"
#include "core/point_locator.h"
#include "core/region/curve_tube.h"
#include "core/tensor_field.h"
#include "tests/core/design/curve_test_meshes.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

struct Closest {
  double distance = 1e300;
  int segment = -1;
  double t = 0;
};

/// Brute force: closest point of the sample polyline to p, over every segment.
Closest bruteClosest(const CurveElement& c, const Vec3& p) {
  Closest best;
  const std::size_t n = c.samples.size();
  const std::size_t segments = c.closed ? n : n - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const Vec3 a = c.samples[s].origin, b = c.samples[(s + 1) % n].origin;
    if ((p - a).norm() - (b - a).norm() > best.distance) continue;  // cannot be closer
    // Ternary search on the convex distance along the segment (independent of the closed-form
    // projection used by the code under test).
    double lo = 0, hi = 1;
    for (int it = 0; it < 80; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if ((p - (a + m1 * (b - a))).norm() < (p - (a + m2 * (b - a))).norm())
        hi = m2;
      else
        lo = m1;
    }
    const double t = 0.5 * (lo + hi);
    const double d = (p - (a + t * (b - a))).norm();
    if (d < best.distance) best = {d, static_cast<int>(s), t};
  }
  return best;
}

CurveOptions wavyOpen() {
  CurveOptions o;
  o.points = {{-0.7, -0.3, -0.2}, {-0.2, 0.2, 0.1}, {0.3, -0.1, 0.3}, {0.7, 0.3, -0.1}};
  o.spacing = 0.05;
  o.radius = 0.22;
  return o;
}

CurveOptions tiltedLoop() {
  CurveOptions o;
  for (int i = 0; i < 8; ++i) {
    const double s = 2 * kPi * i / 8;
    o.points.push_back({0.5 * std::cos(s), 0.5 * std::sin(s), 0.15 * std::sin(2 * s)});
  }
  o.closed = true;
  o.spacing = 0.05;
  o.radius = 0.2;
  return o;
}

TEST(CurveConstraint, TubeIsExactlyTheVerticesWithinTheRadiusOnAConvexMesh) {
  const auto mesh = testing::jitteredBox(16, 0.2);
  for (const CurveOptions& o : {wavyOpen(), tiltedLoop()}) {
    const CurveElement c = buildCurveElement(o);
    std::vector<Vec3> poly;
    for (const auto& s : c.samples) poly.push_back(s.origin);
    const TubeQuery tube = findTubeVertices(*mesh, poly, c.closed, c.radius);
    EXPECT_TRUE(tube.pointsOutside.empty());
    std::set<int> expected;
    for (int v = 0; v < static_cast<int>(mesh->vertexCount()); ++v) {
      if (bruteClosest(c, mesh->positions()[v]).distance <= c.radius) expected.insert(v);
    }
    ASSERT_GT(expected.size(), 50u);
    std::set<int> got;
    for (const auto& tv : tube.vertices) {
      got.insert(tv.vertex);
      const Closest b = bruteClosest(c, mesh->positions()[tv.vertex]);
      EXPECT_NEAR(tv.distance, b.distance, 1e-9);
    }
    EXPECT_EQ(got, expected);
    for (std::size_t k = 1; k < tube.vertices.size(); ++k) {
      EXPECT_LT(tube.vertices[k - 1].vertex, tube.vertices[k].vertex);
    }
  }
}

TEST(CurveConstraint, TubeDoesNotJumpAcrossASlotInTheVolume) {
  // A slot |x| < 0.1 cut down from the top (y > −0.5): a curve at x = −0.25 has Euclidean
  // neighbours across the slot, but they are not reachable through the volume inside the tube.
  const auto box = testing::jitteredBox(20, 0.1);
  const auto mesh = testing::keepTets(
      *box, [](const Vec3& c) { return !(std::abs(c.x()) < 0.1 && c.y() > -0.5); });
  CurveOptions o;
  o.points = {{-0.25, 0.4, -0.8}, {-0.25, 0.4, 0.8}};
  o.radius = 0.45;
  const CurveElement c = buildCurveElement(o);
  std::vector<Vec3> poly;
  for (const auto& s : c.samples) poly.push_back(s.origin);
  const TubeQuery tube = findTubeVertices(*mesh, poly, false, o.radius);
  ASSERT_FALSE(tube.vertices.empty());
  int farSideWithinRadius = 0;
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); ++v) {
    const Vec3& p = mesh->positions()[v];
    if (p.x() > 0 && bruteClosest(c, p).distance <= o.radius) ++farSideWithinRadius;
  }
  EXPECT_GT(farSideWithinRadius, 10);
  for (const auto& tv : tube.vertices) EXPECT_LT(mesh->positions()[tv.vertex].x(), 0);
}

TEST(CurveConstraint, FixedValuesAreTheLinearisationAtTheClosestCurvePoint) {
  const auto mesh = testing::jitteredBox(14, 0.2);
  for (const CurveOptions& base : {wavyOpen(), tiltedLoop()}) {
    CurveOptions o = base;
    o.pattern = DegeneratePattern::Trisector;
    o.rotation = Vec3(10, 20, 30);
    const CurveElement c = buildCurveElement(o);
    FixedValueAccumulator acc(mesh->vertexCount());
    const CurveApplyReport report = applyCurveElement(*mesh, c, acc);
    const FixedValues fixed = acc.finish();
    EXPECT_EQ(fixed.vertices.size(), report.tubeVertices);
    EXPECT_EQ(report.shared, 0u);
    EXPECT_LE(report.maxDistance, o.radius);
    const std::size_t n = c.samples.size();
    for (std::size_t k = 0; k < fixed.vertices.size(); ++k) {
      const Vec3& p = mesh->positions()[fixed.vertices[k]];
      const Closest b = bruteClosest(c, p);
      const auto& A = c.samples[b.segment];
      const auto& B = c.samples[(b.segment + 1) % n];
      const Vec3 q = (1 - b.t) * A.origin + b.t * B.origin;
      // Expected: the frame rotated from A's towards B's by the fraction t of their relative
      // rotation (built here with a quaternion slerp), values blended linearly.
      const Eigen::Quaterniond qa(A.frame), qb(B.frame);
      LocalLinearization l = A;
      l.origin = q;
      l.frame = qa.slerp(b.t, qb).toRotationMatrix();
      const Tensor expected = l.evaluate(p);  // same T0 and Jacobian on every sample
      EXPECT_LT((fixed.values[k] - expected).norm(), 1e-6) << fixed.vertices[k];
    }
  }
}

TEST(CurveConstraint, StraightDegenerateCurveIsExactlyDegenerateInTheFixedValues) {
  // On a straight curve every sample has the same frame, so the fixed values are one linear
  // field; its piecewise-linear interpolation is degenerate exactly on the curve.
  const auto mesh = testing::jitteredBox(12, 0.2);
  const Vec3 a(-0.8, -0.5, -0.6), b(0.7, 0.6, 0.5);
  for (auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
    CurveOptions o;
    o.points = {a, b};
    o.type = type;
    o.radius = 0.4;
    o.spacing = 0.1;
    const CurveElement c = buildCurveElement(o);
    FixedValueAccumulator acc(mesh->vertexCount());
    applyCurveElement(*mesh, c, acc);
    const FixedValues fixed = acc.finish();
    std::vector<Tensor> values(mesh->vertexCount());
    std::vector<char> isFixed(mesh->vertexCount(), 0);
    for (std::size_t k = 0; k < fixed.vertices.size(); ++k) {
      values[fixed.vertices[k]] = fixed.values[k];
      isFixed[fixed.vertices[k]] = 1;
      EXPECT_LT(
          (fixed.values[k] - c.samples[0].evaluate(mesh->positions()[fixed.vertices[k]])).norm(),
          1e-12);
    }
    const TensorField field(mesh, values);
    int checked = 0;
    for (int k = 1; k < 50; ++k) {
      const Vec3 p = a + (b - a) * (k / 50.0);
      const auto loc = mesh->locator().locate(p);
      ASSERT_TRUE(loc);
      bool allFixed = true;
      for (int v : mesh->tets()[loc->tet]) allFixed = allFixed && isFixed[v];
      if (!allFixed) continue;  // near the caps
      ++checked;
      const Tensor t = field.interpolate(loc->tet, loc->barycentric);
      // Repeated eigenvalues to rounding (a point 1e-3 off the curve would split them ~1e-3).
      const Vec3 l = eigenDecompose(t).values;
      const double gap = type == DegenerateType::Linear ? l[1] - l[2] : l[0] - l[1];
      EXPECT_LT(gap, 1e-12 * t.norm());
      EXPECT_EQ(classify(t, 1e-6),
                type == DegenerateType::Linear ? TensorType::Linear : TensorType::Planar);
    }
    EXPECT_GT(checked, 40);
  }
}

TEST(CurveConstraint, OverlappingTubesBlendWithDistanceWeights) {
  const auto mesh = testing::jitteredBox(14, 0.2);
  CurveOptions first;
  first.points = {{-0.8, 0, 0}, {0.8, 0, 0}};
  first.radius = 0.3;
  CurveOptions second = first;
  second.points = {{0, -0.8, 0.1}, {0, 0.8, 0.1}};
  second.type = DegenerateType::Planar;
  const CurveElement c1 = buildCurveElement(first), c2 = buildCurveElement(second);
  FixedValueAccumulator both(mesh->vertexCount()), only1(mesh->vertexCount()),
      only2(mesh->vertexCount());
  applyCurveElement(*mesh, c1, both);
  const CurveApplyReport r2 = applyCurveElement(*mesh, c2, both);
  applyCurveElement(*mesh, c1, only1);
  applyCurveElement(*mesh, c2, only2);
  const FixedValues f = both.finish(), f1 = only1.finish(), f2 = only2.finish();
  EXPECT_GT(f.conflicts, 0u);
  EXPECT_EQ(r2.shared, f.conflicts);
  const double eps = kCurveBlendEpsilon * mesh->meanEdgeLength();
  std::map<int, Tensor> v1, v2;
  for (std::size_t k = 0; k < f1.vertices.size(); ++k) v1[f1.vertices[k]] = f1.values[k];
  for (std::size_t k = 0; k < f2.vertices.size(); ++k) v2[f2.vertices[k]] = f2.values[k];
  int blended = 0;
  for (std::size_t k = 0; k < f.vertices.size(); ++k) {
    const int v = f.vertices[k];
    const Vec3& p = mesh->positions()[v];
    if (v1.count(v) && v2.count(v)) {
      ++blended;
      const double d1 = bruteClosest(c1, p).distance, d2 = bruteClosest(c2, p).distance;
      const double w1 = 1 / (d1 * d1 + eps * eps), w2 = 1 / (d2 * d2 + eps * eps);
      const Tensor expected = (v1[v] * w1 + v2[v] * w2) * (1 / (w1 + w2));
      EXPECT_LT((f.values[k] - expected).norm(), 1e-12);
      // The nearer curve dominates.
      if (d1 < 0.3 * d2) {
        EXPECT_LT((f.values[k] - v1[v]).norm(), (f.values[k] - v2[v]).norm());
      }
    } else {
      EXPECT_EQ(f.values[k], v1.count(v) ? v1[v] : v2[v]);
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(blended), f.conflicts);
}

TEST(CurveConstraint, SameResultForOneAndTwoThreads) {
  std::vector<FixedValues> results;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const auto mesh = testing::carvedBall(14);
    FixedValueAccumulator acc(mesh->vertexCount());
    CurveOptions o = tiltedLoop();
    applyCurveElement(*mesh, buildCurveElement(o), acc);
    applyCurveElement(*mesh, buildCurveElement(wavyOpen()), acc);
    results.push_back(acc.finish());
  }
  EXPECT_EQ(results[0].vertices, results[1].vertices);
  EXPECT_EQ(results[0].values, results[1].values);
}

TEST(CurveConstraint, RefusesBadCurves) {
  const auto mesh = testing::carvedBall(10);
  FixedValueAccumulator acc(mesh->vertexCount());
  const auto expectError = [&](const CurveElement& c, const std::string& text) {
    try {
      applyCurveElement(*mesh, c, acc);
      ADD_FAILURE() << "no error, expected: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  CurveOptions o;
  o.points = {{-0.5, 0, 0}, {0.5, 0.1, 0}};
  o.radius = 0.2;
  const CurveElement good = buildCurveElement(o);
  CurveElement c = good;
  c.radius = 0;
  expectError(c, "tube radius must be a positive number");
  c = good;
  c.samples.resize(1);
  expectError(c, "at least 2 samples");
  c = good;
  c.closed = true;
  c.samples.resize(2);
  expectError(c, "at least 3 samples");
  o.points = {{-0.5, 0, 0}, {1.5, 0.1, 0}};  // leaves the ball
  expectError(buildCurveElement(o), "lies outside the mesh");
  o.points = {{2, 2, 2}, {3, 2, 2}};  // entirely outside
  expectError(buildCurveElement(o), "lies outside the mesh");
  o.points = {{-0.5, 0, 0}, {0.5, 0.1, 0}};
  o.radius = 1e-5;  // thinner than the mesh: no vertex inside
  c = buildCurveElement(o);
  c.samples.front().origin += Vec3(1e-3, 1.3e-3, 0.7e-3);  // away from any vertex
  c.samples.back().origin += Vec3(1e-3, 1.3e-3, 0.7e-3);
  for (auto& s : c.samples) s.origin += Vec3(0.011, 0.013, 0.017);
  expectError(c, "no mesh vertex lies within the tube radius");
  c = good;
  c.samples[3].frame.col(0) *= 2;
  expectError(c, "sample 3 has a non-finite position or a frame that is not a rotation");
  FixedValueAccumulator wrong(3);
  EXPECT_THROW(applyCurveElement(*mesh, good, wrong), Error);
  EXPECT_EQ(acc.claimedCount(), 0u);  // failures add nothing
}

}  // namespace
}  // namespace tfd::core
