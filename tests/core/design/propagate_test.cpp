// Propagation (core/design/propagate.h, paper §5): design values kept, harmonic elsewhere,
// boundary-conforming second solve (Eq. 4), curvature boundary, errors, determinism.
#include "core/design/propagate.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/design/apply_constraints.h"
#include "core/design/boundary_conforming.h"
#include "core/error.h"
#include "core/solve/laplacian.h"
#include "tests/core/solve/solver_test_meshes.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

using testing::maxDifference;

ConstraintSet wedgeAndTensor() {
  ConstraintSet set;
  PointElement wedge;
  wedge.field =
      makeDegenerateLinearization(Vec3(0.1, 0.05, -0.1), rotationFromEulerDegrees(Vec3(20, 30, 40)),
                                  DegenerateType::Linear, DegeneratePattern::Wedge);
  wedge.degenerate = true;
  PointElement tensor;
  tensor.field = makeTensorLinearization(
      Vec3(-0.4, 0.3, 0.2), rotationFromEulerDegrees(Vec3(0, 45, 0)), Vec3(1, 0.2, -0.8));
  tensor.radius = 0.2;
  set.points = {wedge, tensor};
  return set;
}

/// ‖Tn − (nᵀTn)n‖ / ‖T‖: zero when n is an eigenvector.
double eigenvectorDefect(const Tensor& t, const Vec3& n) {
  const Vec3 tn = t.matrix() * n;
  return (tn - n.dot(tn) * n).norm() / std::max(t.norm(), 1e-300);
}

/// Worst relative discrete Laplacian over the free vertices (fixed = not free).
double harmonicDefect(const TensorField& f, const std::vector<unsigned char>& fixed) {
  std::vector<int> free;
  for (std::size_t v = 0; v < fixed.size(); ++v)
    if (!fixed[v]) free.push_back(static_cast<int>(v));
  const StiffnessRows rows = assembleStiffnessRows(f.mesh(), free);
  double worst = 0;
  for (int c = 0; c < 5; ++c) {
    std::vector<double> u(fixed.size()), held(fixed.size(), 0.0);
    for (std::size_t v = 0; v < fixed.size(); ++v) {
      u[v] = f.at(static_cast<int>(v)).vec5()[c];
      if (fixed[v]) held[v] = u[v];
    }
    const auto ku = applyStiffness(rows, u), kb = applyStiffness(rows, held);
    double d = 0, r = 0;
    for (std::size_t i = 0; i < ku.size(); ++i) d += ku[i] * ku[i], r += kb[i] * kb[i];
    if (r > 0) worst = std::max(worst, std::sqrt(d / r));
  }
  return worst;
}

TEST(Propagate, BoundaryConformingFieldHasTheNormalAsEigenvectorEverywhereOnTheBoundary) {
  const auto mesh = test::mappedBall(15);  // 20250 tets
  const ConstraintSet set = wedgeAndTensor();
  const PropagateResult result = propagate(mesh, set);
  const FixedValues design = applyConstraints(*mesh, set);
  EXPECT_EQ(result.report.designVertices, design.vertices.size());
  EXPECT_GT(result.report.boundaryVertices, 0u);
  EXPECT_GT(result.report.firstIterations, 0);
  EXPECT_GT(result.report.secondIterations, 0);
  for (int v : mesh->boundaryVertices()) {
    const Vec3& n = mesh->vertexNormals()[v];
    EXPECT_LE(eigenvectorDefect(result.field.at(v), n), 1e-6) << "vertex " << v;
  }
  // Design vertices keep their values; the field is traceless and harmonic elsewhere.
  for (std::size_t i = 0; i < design.vertices.size(); ++i)
    EXPECT_LT(maxDifference(result.field.at(design.vertices[i]), design.values[i].deviator()),
              1e-15);
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  for (int v : design.vertices) fixed[v] = 1;
  for (int v : mesh->boundaryVertices()) fixed[v] = 1;
  EXPECT_LT(harmonicDefect(result.field, fixed), 1e-6);
  for (const Tensor& t : result.field.values()) EXPECT_NEAR(t.trace(), 0, 1e-12);
}

TEST(Propagate, WithoutBoundaryConformingOneSolveWithNaturalBoundary) {
  const auto mesh = testing::jitteredBox(8);
  const ConstraintSet set = wedgeAndTensor();
  PropagateOptions options;
  options.boundaryConforming = false;
  const PropagateResult result = propagate(mesh, set, options);
  EXPECT_EQ(result.report.secondIterations, 0);
  EXPECT_EQ(result.report.boundaryVertices, 0u);
  const FixedValues design = applyConstraints(*mesh, set);
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  for (int v : design.vertices) fixed[v] = 1;
  EXPECT_LT(harmonicDefect(result.field, fixed), 1e-6);
  // Generic Neumann solution: the normal is not an eigenvector on the boundary.
  double worst = 0;
  for (int v : mesh->boundaryVertices())
    worst = std::max(worst, eigenvectorDefect(result.field.at(v), mesh->vertexNormals()[v]));
  EXPECT_GT(worst, 1e-3);
}

TEST(Propagate, ConformToNormalIsEquation4) {
  const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
  const Tensor t = Tensor{0.4, -0.1, -0.3, 0.7, -0.2, 0.5};
  const Tensor c = conformToNormal(t, n * 3.0);
  EXPECT_LT(eigenvectorDefect(c, n), 1e-15);
  EXPECT_NEAR(c.trace(), t.trace(), 1e-15);
  // In a frame (u, v, n): the tangent block and the normal entry are unchanged.
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  Mat3 frame;
  frame << u, w, n;
  const Mat3 before = frame.transpose() * t.matrix() * frame;
  const Mat3 after = frame.transpose() * c.matrix() * frame;
  EXPECT_LT(((before.topLeftCorner<2, 2>() - after.topLeftCorner<2, 2>()).norm()), 1e-15);
  EXPECT_NEAR(before(2, 2), after(2, 2), 1e-15);
  EXPECT_LT((after.topRightCorner<2, 1>().norm()), 1e-15);
}

TEST(Propagate, CurvatureBoundaryOnASphereGivesTheLiftedUmbilicTensor) {
  const auto mesh = test::mappedBall(15, 2.0);
  PropagateOptions options;
  options.curvatureBoundary = true;
  options.normalEigenvalue = 1.5;
  const PropagateResult result = propagate(mesh, ConstraintSet{}, options);  // no design needed
  // Boundary: deviator of (1/r)(I − nnᵀ) + λ nnᵀ = (λ − 1/r)(nnᵀ − I/3).
  double worst = 0;
  for (int v : mesh->boundaryVertices()) {
    const Vec3& n = mesh->vertexNormals()[v];
    const Tensor expected =
        Tensor::fromMatrix((1.5 - 0.5) * (n * n.transpose() - Mat3::Identity() / 3));
    worst = std::max(worst, maxDifference(result.field.at(v), expected));
    EXPECT_LE(eigenvectorDefect(result.field.at(v), n), 1e-12);
  }
  EXPECT_LT(worst, 0.05);
  EXPECT_EQ(result.report.firstIterations, 0);
  EXPECT_GT(result.report.secondIterations, 0);
}

TEST(Propagate, ErrorsAreClear) {
  const auto mesh = makeBoxMesh(4, 4, 4, Vec3(0, 0, 0), Vec3(1, 1, 1));
  try {
    propagate(mesh, ConstraintSet{});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no design element"), std::string::npos) << e.what();
  }
  ConstraintSet outside;
  PointElement p;
  p.field = makeTensorLinearization(Vec3(3, 0, 0), Mat3::Identity(), Vec3(1, 0, -1));
  outside.points = {p};
  EXPECT_THROW(propagate(mesh, outside), Error);
  PropagateOptions bad;
  bad.tolerance = 0;
  EXPECT_THROW(propagate(mesh, wedgeAndTensor(), bad), Error);
}

TEST(Propagate, BitwiseEqualForOneAndTwoThreads) {
  const auto mesh = test::carvedSolid(
      30, Vec3(-3, -1.5, -0.5), Vec3(3, 1.5, 0.5),
      [](const Vec3& p) { return test::insideDoubleTorus(p); }, 0.15);
  ConstraintSet set;
  PointElement p;
  p.field = makeDegenerateLinearization(Vec3(2.2, 0.0, 0.0), Mat3::Identity(),
                                        DegenerateType::Planar, DegeneratePattern::Trisector);
  set.points = {p};
  PropagateOptions o;
  o.reuseSetups = false;  // each run builds its own set-ups
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    return propagate(mesh, set, o);
  };
  const PropagateResult one = run(1), two = run(2);
  ASSERT_EQ(one.field.values().size(), two.field.values().size());
  for (std::size_t v = 0; v < one.field.values().size(); ++v)
    ASSERT_EQ(one.field.values()[v], two.field.values()[v]) << v;
}

TEST(Propagate, CancellationIsHonoured) {
  const auto mesh = testing::jitteredBox(6);
  std::atomic<bool> cancel{true};
  EXPECT_THROW(propagate(mesh, wedgeAndTensor(), {}, Progress({}, &cancel)), Cancelled);
}

}  // namespace
}  // namespace tfd::core
