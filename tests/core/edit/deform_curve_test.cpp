// Degenerate curve deformation (paper §6.1; core/edit/deform_curve.h) on fields whose curves
// are known exactly (removal_test_fields.h): a straight curve bent onto a target, one of two
// curves moved, independent checks of the result, fold-overs on an extreme target, refusals, and
// 1 vs 2 threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "core/derived_cache.h"
#include "core/edit/deform_curve.h"
#include "core/edit/deform_paths.h"
#include "core/region/ball_check.h"
#include "core/region/region_vertices.h"
#include "core/topology/curve_tets.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/removal_test_fields.h"

namespace tfd::core {
namespace {

using testing::Complex;

/// One straight open curve, the z axis (x = y = 0): with the tilted constant frame it is a
/// pure curve (its tangent is never ⊥ e).
Complex zAxis(const Vec3& p) { return {p.x(), p.y()}; }

std::shared_ptr<const TetMesh> box() {
  static const auto mesh = testing::jitteredBox(18, 0.15);
  return mesh;
}

/// A smooth bump off the z axis between z = ±0.45, `height` at z = 0, in the direction d.
std::vector<Vec3> bump(double height, const Vec3& d = Vec3(1, 0.4, 0).normalized()) {
  std::vector<Vec3> t;
  for (int i = 0; i <= 12; ++i) {
    const double z = -0.45 + 0.9 * i / 12;
    const double c = std::cos(std::numbers::pi * z / 0.9);
    t.push_back(height * c * c * d + Vec3(0, 0, z));
  }
  return t;
}

bool bitwiseEqual(const Tensor& a, const Tensor& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Directed distance from every point of `a` to the polyline `b`.
double farthest(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double h = 0;
  for (const Vec3& p : a) h = std::max(h, distanceToPolyline(p, b));
  return h;
}

TEST(DeformCurve, BendsAStraightCurveOntoTheTarget) {
  const auto mesh = box();
  const TensorField field = testing::designedField(mesh, zAxis);
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 1u) << before.summary();
  DeformCurveOptions o;
  o.pick = Vec3(0.01, 0, 0.1);
  o.target = bump(0.3);
  const DeformCurveResult r = deformCurve(field, o);
  ASSERT_EQ(r.curves.size(), 1u) << r.curves.summary();
  ASSERT_FALSE(r.report.tries.empty());
  EXPECT_TRUE(r.report.tries.back().failedCheck.empty());
  EXPECT_EQ(r.report.foldOversOnCurve, 0u);
  EXPECT_GT(r.report.envelopeVertices, 0u);
  EXPECT_LE(r.report.hausdorff, r.report.tolerance);
  // Independent checks. The curve moved: its point nearest the bump's top is at the target,
  // not on the z axis; it follows the target within one mean edge length; outside the region's
  // free vertices nothing changed bitwise; the region is a ball; re-extraction agrees.
  const DegenerateCurve& c = r.curves.curve(0);
  const double h = mesh->meanEdgeLength();
  std::vector<Vec3> middle;  // the new curve's points along the bump (|z| < 0.4)
  for (const Vec3& p : c.points)
    if (std::abs(p.z()) < 0.4) middle.push_back(p);
  ASSERT_FALSE(middle.empty());
  EXPECT_LE(farthest(middle, o.target), h);
  EXPECT_LE(farthest(resamplePolyline(o.target, 50), c.points), h);
  double highest = 0;
  for (const Vec3& p : middle) highest = std::max(highest, std::hypot(p.x(), p.y()));
  EXPECT_GT(highest, 0.3 - h);
  // Away from the bump the curve is still the z axis.
  for (const Vec3& p : c.points)
    if (std::abs(p.z()) > 0.7) {
      EXPECT_LE(std::hypot(p.x(), p.y()), 1e-6) << p.transpose();
    }
  EXPECT_TRUE(checkTopologicalBall(*mesh, r.regionTets).ball);
  const RegionVertices rv = regionVertices(*mesh, r.regionTets);
  std::vector<char> isFree(mesh->vertexCount(), 0);
  for (int v : rv.free) isFree[v] = 1;
  int changed = 0;
  for (int v = 0; v < int(mesh->vertexCount()); ++v) {
    if (isFree[v])
      changed += !bitwiseEqual(field.at(v), r.field.at(v));
    else
      ASSERT_TRUE(bitwiseEqual(field.at(v), r.field.at(v))) << "vertex " << v;
  }
  EXPECT_GT(changed, 0);
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), 1u);
  EXPECT_NE(r.report.lines().back().find("1 curves -> 1"), std::string::npos);
  EXPECT_EQ(c.type, before.curve(0).type);
  const std::vector<std::string> lines = r.report.lines();
  EXPECT_NE(
      lines[2].find("fold-overs: " + std::to_string(r.report.foldOvers) + " (0 on the curve)"),
      std::string::npos)
      << lines[2];
}

TEST(DeformCurve, BendsOneOfTwoCurvesAndLeavesTheOtherAlone) {
  // Two straight curves x = ±0.5; the one at x = −0.5 is bent away from the other.
  const auto mesh = box();
  const TensorField field =
      testing::designedField(mesh, [](const Vec3& p) { return testing::twoLinesW(p, 0.5); });
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 2u) << before.summary();
  DeformCurveOptions o;
  o.pick = Vec3(-0.5, 0, 0);
  o.target = bump(0.2, Vec3(-1, 0, 0));
  for (Vec3& p : o.target) p.x() -= 0.5;
  o.regionDistance = 0.2;
  const DeformCurveResult r = deformCurve(field, o);
  ASSERT_EQ(r.curves.size(), 2u) << r.curves.summary();
  // The other curve is unchanged point for point (verification check 2), and the moved one
  // reaches x ≈ −0.7.
  double leftmost = 0;
  for (const DegenerateCurve& c : r.curves.curves())
    for (const Vec3& p : c.points) leftmost = std::min(leftmost, p.x());
  EXPECT_NEAR(leftmost, -0.7, mesh->meanEdgeLength());
}

TEST(DeformCurve, MovesAnArcOfALoopOnEitherSideOfItsFirstPoint) {
  // The mixed loop x² + z² = 0.4², y = 0 starts near (−0.4, 0, 0) (canonical order), so the
  // arc there wraps around the loop's first point and the arc at (0.4, 0, 0) does not.
  const auto mesh = box();
  const TensorField field =
      testing::designedField(mesh, [](const Vec3& p) { return testing::loopW(p); });
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 1u);
  for (const double side : {1.0, -1.0}) {
    SCOPED_TRACE(side);
    DeformCurveOptions o;
    o.pick = Vec3(0.4 * side, 0, 0);
    for (int i = 0; i <= 8; ++i) {  // from angle −35° to 35° around the pick, out to 0.58
      const double a = (-35 + 70.0 * i / 8) * std::numbers::pi / 180;
      const double r = 0.4 + 0.18 * std::pow(std::cos(a * 90 / 35), 2);
      o.target.push_back(Vec3(side * r * std::cos(a), 0, r * std::sin(a)));
    }
    o.regionDistance = 0.25;
    const DeformCurveResult r = deformCurve(field, o);
    ASSERT_EQ(r.curves.size(), 1u) << r.curves.summary();
    const DegenerateCurve& c = r.curves.curve(0);
    EXPECT_TRUE(c.closed);
    double outermost = 0;
    for (const Vec3& p : c.points) outermost = std::max(outermost, side * p.x());
    EXPECT_NEAR(outermost, 0.58, mesh->meanEdgeLength());
    // The other side of the loop did not move: its points are the old ones.
    for (const Vec3& p : c.points) {
      if (side * p.x() > -0.2) continue;
      double nearest = 1;
      for (const Vec3& q : before.curve(0).points) nearest = std::min(nearest, (p - q).norm());
      EXPECT_LE(nearest, 1e-12) << p.transpose();
    }
  }
}

TEST(DeformCurve, ReportsFoldOversOnAnExtremeTargetAndFailsThatTry) {
  const auto mesh = box();
  const TensorField field = testing::designedField(mesh, zAxis);
  DeformCurveOptions o;
  o.pick = Vec3(0, 0, 0);
  // A Z that folds back through the region: the map must turn tets inside out.
  o.target = {Vec3(0, 0, -0.3), Vec3(0.5, 0, 0.5), Vec3(-0.5, 0, -0.5), Vec3(0, 0, 0.3)};
  o.retries = 1;
  try {
    deformCurve(field, o);
    FAIL() << "an extreme target was accepted";
  } catch (const DeformationFailed& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("check 'no fold-over on the curve' failed"), std::string::npos) << m;
    EXPECT_NE(m.find("inverted tets of the map hold the target"), std::string::npos) << m;
    EXPECT_NE(m.find("last region "), std::string::npos) << m;
    // The tets holding the target map by the target alone: a larger region is not tried.
    EXPECT_NE(m.find("failed after 1 try:"), std::string::npos) << m;
    EXPECT_NE(m.find("no larger region is tried"), std::string::npos) << m;
  }
}

TEST(DeformCurve, RefusesBadInput) {
  const auto mesh = box();
  const TensorField field = testing::designedField(mesh, zAxis);
  DeformCurveOptions o;
  o.pick = Vec3(0, 0, 0);
  o.target = {Vec3(0, 0, 0.2)};
  EXPECT_THROW(deformCurve(field, o), Error);  // one point
  o.target = {Vec3(0, 0, -0.2), Vec3(3, 0, 0), Vec3(0, 0, 0.2)};
  try {
    deformCurve(field, o);
    FAIL() << "a target outside the mesh was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("target: the point"), std::string::npos) << e.what();
  }
  o.target = {Vec3(0.1, 0, 0.2), Vec3(0.2, 0, 0.2)};  // both ends meet the curve at one place
  EXPECT_THROW(deformCurve(field, o), Error);
  // A target through another curve cannot be held by a ball without it.
  const TensorField two =
      testing::designedField(mesh, [](const Vec3& p) { return testing::twoLinesW(p); });
  o.pick = Vec3(-0.3, 0, 0);
  o.target = {Vec3(-0.3, 0, -0.3), Vec3(0.3, 0, 0), Vec3(-0.3, 0, 0.3)};
  try {
    deformCurve(two, o);
    FAIL() << "a target through another curve was accepted";
  } catch (const DeformationFailed& e) {
    FAIL() << e.what();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("would cut"), std::string::npos) << e.what();
  }
}

TEST(DeformCurve, OneAndTwoThreadsAgreeBitwise) {
  const auto mesh = box();
  const TensorField field = testing::designedField(mesh, zAxis);
  DeformCurveOptions o;
  o.pick = Vec3(0, 0, 0);
  o.target = bump(0.2);
  o.regionDistance = 0.3;
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    derivedCache().clear();  // each run builds its own solver set-up
    return deformCurve(field, o).field;
  };
  const TensorField one = run(1), two = run(2);
  for (int v = 0; v < int(mesh->vertexCount()); ++v)
    ASSERT_TRUE(bitwiseEqual(one.at(v), two.at(v))) << "vertex " << v;
}

}  // namespace
}  // namespace tfd::core
