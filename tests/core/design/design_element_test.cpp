// Design elements (core/design/design_element.h, paper §5 Eq. 2–3), the fixed-value
// accumulator and applyConstraints.
#include "core/design/design_element.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/design/apply_constraints.h"
#include "core/design/fixed_values.h"
#include "core/error.h"
#include "core/point_locator.h"
#include "core/structured_mesh.h"
#include "tests/core/solve/solver_test_meshes.h"

namespace tfd::core {
namespace {

using testing::maxDifference;

Tensor fromRows(const Mat3& m) { return Tensor::fromMatrix(m); }

TEST(DesignElement, DefaultLinearWedgeIsFieldF1) {
  const auto l = makeDegenerateLinearization(Vec3::Zero(), Mat3::Identity(), DegenerateType::Linear,
                                             DegeneratePattern::Wedge);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.3, -0.2, 0.7), Vec3(-0.5, 0.4, -1)}) {
    Mat3 a;
    a << p.x() - 1, p.y(), 0, p.y(), -p.x() - 1, 0, 0, 0, 2;
    EXPECT_LT(maxDifference(l.evaluate(p), fromRows(a)), 1e-15);
  }
  const EigenDecomposition e = eigenDecompose(l.evaluate(Vec3::Zero()));
  EXPECT_NEAR(e.values[0], 2, 1e-14);
  EXPECT_NEAR(e.values[1], -1, 1e-14);
  EXPECT_NEAR(e.values[2], -1, 1e-14);
  EXPECT_NEAR(std::abs(e.vectors.col(0).z()), 1, 1e-14);
}

TEST(DesignElement, DefaultPlanarPatternsAreFieldF3) {
  for (auto pattern : {DegeneratePattern::Wedge, DegeneratePattern::Trisector}) {
    const double s = pattern == DegeneratePattern::Wedge ? 1 : -1;
    const auto l = makeDegenerateLinearization(Vec3::Zero(), Mat3::Identity(),
                                               DegenerateType::Planar, pattern);
    const Vec3 p(0.2, 0.3, -0.4);
    Mat3 a;
    a << 1 + p.x(), s * p.y(), 0, s * p.y(), 1 - p.x(), 0, 0, 0, -2;
    EXPECT_LT(maxDifference(l.evaluate(p), fromRows(a)), 1e-15);
    EXPECT_EQ(classify(l.evaluate(Vec3::Zero())), TensorType::Planar);
  }
}

/// δ = (∇α × ∇β)·e at a degenerate point (algorithms note §5.2): > 0 wedge, < 0 trisector,
/// with (u, w, e) right-handed and α = ½(uᵀAu − wᵀAw), β = uᵀAw; gradients by central
/// differences (exact for the linear fields here).
double delta(const LocalLinearization& l, const Vec3& p) {
  const EigenDecomposition ed = eigenDecompose(l.evaluate(p));
  // The non-degenerate eigenvector is the isolated one.
  const bool linear = std::abs(ed.values[0] - ed.values[1]) > std::abs(ed.values[1] - ed.values[2]);
  const Vec3 e = linear ? ed.vectors.col(0) : ed.vectors.col(2);
  const Vec3 u = e.unitOrthogonal();
  const Vec3 w = e.cross(u);
  auto alphaBeta = [&](const Vec3& q) {
    const Mat3 a = l.evaluate(q).matrix();
    return Eigen::Vector2d(0.5 * (u.dot(a * u) - w.dot(a * w)), u.dot(a * w));
  };
  const double h = 1e-4;
  Vec3 ga, gb;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d d =
        (alphaBeta(p + h * Vec3::Unit(i)) - alphaBeta(p - h * Vec3::Unit(i))) / (2 * h);
    ga[i] = d[0];
    gb[i] = d[1];
  }
  // The degenerate curve's tangent is ∇α × ∇β; δ compares it with e.
  return ga.cross(gb).dot(e);
}

TEST(DesignElement, WedgeAndTrisectorFollowTheDeltaSignRuleInAnyFrame) {
  const Vec3 origin(0.3, -0.7, 1.1);
  for (const Vec3& angles : {Vec3(0, 0, 0), Vec3(30, 45, -60), Vec3(-120, 10, 75)}) {
    const Mat3 frame = rotationFromEulerDegrees(angles);
    for (auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
      const auto wedge = makeDegenerateLinearization(origin, frame, type, DegeneratePattern::Wedge);
      const auto tri =
          makeDegenerateLinearization(origin, frame, type, DegeneratePattern::Trisector);
      EXPECT_GT(delta(wedge, origin), 0.5) << angles.transpose();
      EXPECT_LT(delta(tri, origin), -0.5) << angles.transpose();
      EXPECT_EQ(classify(wedge.evaluate(origin)),
                type == DegenerateType::Linear ? TensorType::Linear : TensorType::Planar);
    }
  }
}

TEST(DesignElement, DegenerateLineRunsAlongTheFrameZAxis) {
  const Vec3 origin(1, 2, 3);
  const Mat3 frame = rotationFromEulerDegrees(Vec3(20, -35, 50));
  const auto l =
      makeDegenerateLinearization(origin, frame, DegenerateType::Linear, DegeneratePattern::Wedge);
  for (double t : {-0.8, -0.1, 0.0, 0.5, 1.2}) {
    const Tensor on = l.evaluate(origin + t * frame.col(2));
    EXPECT_LT(normalizedDiscriminant(on), 1e-20) << t;
    // The non-degenerate (major) eigenvector is the frame's z axis.
    EXPECT_NEAR(std::abs(eigenDecompose(on).vectors.col(0).dot(frame.col(2))), 1, 1e-12);
    const Tensor off = l.evaluate(origin + t * frame.col(2) + 0.3 * frame.col(0));
    EXPECT_GT(normalizedDiscriminant(off), 1e-4) << t;
  }
}

TEST(DesignElement, RotatedFrameRotatesTheField) {
  const Vec3 origin(-0.4, 0.2, 0.9);
  const Mat3 r = rotationFromEulerDegrees(Vec3(15, 70, -25));
  const auto local = makeDegenerateLinearization(
      Vec3::Zero(), Mat3::Identity(), DegenerateType::Planar, DegeneratePattern::Trisector);
  const auto world =
      makeDegenerateLinearization(origin, r, DegenerateType::Planar, DegeneratePattern::Trisector);
  const Vec3 d(0.3, -0.6, 0.2);
  EXPECT_LT(maxDifference(world.evaluate(origin + r * d), local.evaluate(d).rotated(r)), 1e-14);
}

TEST(DesignElement, TensorElementHasTheGivenEigenvectorsAndTracelessEigenvalues) {
  const Mat3 frame = rotationFromEulerDegrees(Vec3(10, 20, 30));
  const auto l = makeTensorLinearization(Vec3(1, 1, 1), frame, Vec3(3, 1, -1));
  const Tensor t = l.evaluate(Vec3(5, -2, 0));  // constant field
  EXPECT_NEAR(t.trace(), 0, 1e-14);
  const EigenDecomposition e = eigenDecompose(t);
  EXPECT_NEAR(e.values[0], 3 - 1, 1e-13);
  EXPECT_NEAR(e.values[1], 1 - 1, 1e-13);
  EXPECT_NEAR(e.values[2], -1 - 1, 1e-13);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(e.vectors.col(i).dot(frame.col(i))), 1, 1e-12);
  Mat3 skew = Mat3::Identity();
  skew(0, 1) = 0.5;
  EXPECT_THROW(makeTensorLinearization(Vec3::Zero(), skew, Vec3(1, 0, 0)), Error);
  EXPECT_THROW(makeDegenerateLinearization(Vec3(NAN, 0, 0), Mat3::Identity(),
                                           DegenerateType::Linear, DegeneratePattern::Wedge),
               Error);
}

TEST(DesignElement, EulerAnglesApplyXThenYThenZ) {
  const auto near = [](const Vec3& a, const Vec3& b) { return (a - b).norm() < 1e-14; };
  EXPECT_TRUE(near(rotationFromEulerDegrees(Vec3(90, 0, 0)) * Vec3::UnitY(), Vec3::UnitZ()));
  EXPECT_TRUE(near(rotationFromEulerDegrees(Vec3(0, 0, 90)) * Vec3::UnitX(), Vec3::UnitY()));
  // x first leaves the x axis alone, then y by 90° takes it to −z.
  EXPECT_TRUE(near(rotationFromEulerDegrees(Vec3(90, 90, 0)) * Vec3::UnitX(), -Vec3::UnitZ()));
  const Mat3 r = rotationFromEulerDegrees(Vec3(33, -71, 140));
  EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-14);
  EXPECT_NEAR(r.determinant(), 1, 1e-14);
}

TEST(FixedValues, BlendsByWeightAndCountsConflicts) {
  FixedValueAccumulator acc(10);
  const Tensor a{1, -1, 0, 0, 0, 0}, b{0, 0, 0, 1, 0, 0};
  acc.add(7, a, 1.0);
  acc.add(2, b, 2.0);
  acc.add(7, b, 3.0);
  const FixedValues f = acc.finish();
  ASSERT_EQ(f.vertices, (std::vector<int>{2, 7}));
  EXPECT_LT(maxDifference(f.values[0], b), 1e-15);
  EXPECT_LT(maxDifference(f.values[1], a * 0.25 + b * 0.75), 1e-15);
  EXPECT_EQ(f.conflicts, 1u);
  EXPECT_EQ(f.contributions, 3u);
  EXPECT_THROW(acc.add(10, a, 1), Error);
  EXPECT_THROW(acc.add(1, a, 0), Error);
  EXPECT_THROW(acc.add(1, a, NAN), Error);
  EXPECT_GT(blendWeight(0.1, 0.01), blendWeight(0.2, 0.01));
}

TEST(ApplyConstraints, PointFixesItsTetOrItsBallWithEquation2Values) {
  const auto mesh = makeBoxMesh(6, 6, 6, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  ConstraintSet set;
  PointElement p;
  p.field =
      makeDegenerateLinearization(Vec3(0.11, 0.07, -0.05), rotationFromEulerDegrees(Vec3(10, 0, 0)),
                                  DegenerateType::Linear, DegeneratePattern::Wedge);
  set.points.push_back(p);
  FixedValues f = applyConstraints(*mesh, set);
  ASSERT_EQ(f.vertices.size(), 4u);
  const auto location = mesh->locator().locate(p.field.origin);
  ASSERT_TRUE(location);
  std::vector<int> tet(mesh->tets()[location->tet].begin(), mesh->tets()[location->tet].end());
  std::sort(tet.begin(), tet.end());
  EXPECT_EQ(f.vertices, tet);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_LT(maxDifference(f.values[i], p.field.evaluate(mesh->positions()[f.vertices[i]])),
              1e-14);
  EXPECT_EQ(f.pointElements, 1u);
  EXPECT_EQ(f.conflicts, 0u);

  // With a radius: every vertex within it.
  set.points[0].radius = 0.75;
  f = applyConstraints(*mesh, set);
  std::size_t inside = 0;
  for (const Vec3& q : mesh->positions()) inside += (q - p.field.origin).norm() <= 0.75;
  EXPECT_GE(f.vertices.size(), inside);
  EXPECT_GT(inside, 4u);

  // Two overlapping elements blend and report conflicts.
  PointElement q;
  q.field = makeTensorLinearization(Vec3(0.2, 0.1, 0.0), Mat3::Identity(), Vec3(1, 0, -1));
  q.radius = 0.75;
  set.points.push_back(q);
  f = applyConstraints(*mesh, set);
  EXPECT_GT(f.conflicts, 0u);
  EXPECT_NE(f.summary().find("blended"), std::string::npos);
}

TEST(ApplyConstraints, PointOutsideTheMeshNamesTheElement) {
  const auto mesh = makeBoxMesh(3, 3, 3, Vec3(0, 0, 0), Vec3(1, 1, 1));
  ConstraintSet set;
  PointElement inside, outside;
  inside.field = makeTensorLinearization(Vec3(0.5, 0.5, 0.5), Mat3::Identity(), Vec3(1, 0, -1));
  outside.field = makeTensorLinearization(Vec3(2.5, 0.5, 0.5), Mat3::Identity(), Vec3(1, 0, -1));
  set.points = {inside, outside};
  try {
    applyConstraints(*mesh, set);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("point element 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("outside the mesh"), std::string::npos) << e.what();
  }
  set.points = {inside};
  set.points[0].radius = -1;
  EXPECT_THROW(applyConstraints(*mesh, set), Error);
}

}  // namespace
}  // namespace tfd::core
