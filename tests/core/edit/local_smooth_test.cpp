// LocalSmooth: harmonic re-solve inside a region, everything else unchanged
// (core/edit/local_smooth.h).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/edit/local_smooth.h"
#include "core/error.h"
#include "core/solve/laplacian.h"
#include "tests/core/design/curve_test_meshes.h"

namespace tfd::core {
namespace {

/// A smooth, far-from-harmonic traceless field.
TensorField wavyField(std::shared_ptr<const TetMesh> mesh, double trace = 0) {
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    Tensor t{std::sin(3 * p.x()) + p.y() * p.y(), std::cos(2 * p.y() + p.z()), 0, p.x() * p.z() * 2,
             std::sin(4 * p.z()) * p.x(),         std::cos(3 * p.x() * p.y())};
    t = t.deviator();
    t.xx += trace * (1 + p.x() * p.x()) / 3;
    t.yy += trace * (1 + p.x() * p.x()) / 3;
    t.zz += trace * (1 + p.x() * p.x()) / 3;
    values.push_back(t);
  }
  return TensorField(mesh, values);
}

/// ‖K u‖ at the free rows over ‖K_free,fixed u_fixed‖, worst of the five components: zero for a
/// discrete harmonic field.
double harmonicDefect(const TensorField& f, const std::vector<int>& free) {
  const TetMesh& mesh = f.mesh();
  const StiffnessRows rows = assembleStiffnessRows(mesh, free);
  std::vector<char> isFree(mesh.vertexCount(), 0);
  for (int v : free) isFree[v] = 1;
  double worst = 0;
  for (int c = 0; c < 5; ++c) {
    std::vector<double> u(mesh.vertexCount()), fixedOnly(mesh.vertexCount());
    for (std::size_t v = 0; v < u.size(); ++v) {
      u[v] = f.at(static_cast<int>(v)).vec5()[c];
      fixedOnly[v] = isFree[v] ? 0 : u[v];
    }
    const auto r = applyStiffness(rows, u), b = applyStiffness(rows, fixedOnly);
    double rn = 0, bn = 0;
    for (std::size_t i = 0; i < r.size(); ++i) rn += r[i] * r[i], bn += b[i] * b[i];
    worst = std::max(worst, std::sqrt(rn / std::max(bn, 1e-300)));
  }
  return worst;
}

std::vector<int> freeOf(const TetMesh& mesh, const std::vector<int>& region) {
  std::vector<int> free;
  for (int v : region)
    if (!mesh.isBoundaryVertex(v)) free.push_back(v);
  return free;
}

TEST(LocalSmooth, SphereRegionIsHarmonicInsideAndBitwiseUnchangedOutside) {
  const auto mesh = testing::carvedBall(16);
  const TensorField input = wavyField(mesh);
  LocalSmoothOptions o;
  o.region = SmoothRegionShape::Sphere;
  o.center = Vec3(0.1, -0.05, 0.08);
  o.radius = 0.45;
  o.solver.tolerance = 1e-11;
  const std::vector<int> region = smoothRegionVertices(input, o);
  const std::vector<int> free = freeOf(*mesh, region);
  ASSERT_EQ(free.size(), region.size());  // strictly inside the ball
  ASSERT_GT(free.size(), 150u);
  EXPECT_GT(harmonicDefect(input, free), 1e-2);  // the input is far from harmonic there
  const LocalSmoothResult r = localSmooth(input, o);
  EXPECT_EQ(r.report.regionVertices, region.size());
  EXPECT_EQ(r.report.freeVertices, free.size());
  EXPECT_EQ(r.report.boundaryFixed, 0u);
  EXPECT_LT(harmonicDefect(r.field, free), 1e-9);
  std::vector<char> inRegion(mesh->vertexCount(), 0);
  for (int v : region) inRegion[v] = 1;
  int changed = 0;
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); ++v) {
    if (!inRegion[v]) {
      EXPECT_EQ(r.field.at(v), input.at(v)) << v;
    } else {
      EXPECT_LE((mesh->positions()[v] - o.center).norm(), o.radius);
      changed += !(r.field.at(v) == input.at(v));
    }
  }
  EXPECT_EQ(changed, static_cast<int>(free.size()));
  EXPECT_EQ(&r.field.mesh(), mesh.get());
  EXPECT_NE(r.report.summary().find("smoothed"), std::string::npos);
}

TEST(LocalSmooth, RegionTouchingTheDomainBoundaryKeepsItsBoundaryVertices) {
  const auto mesh = testing::carvedBall(16);
  const TensorField input = wavyField(mesh);
  LocalSmoothOptions o;
  o.region = SmoothRegionShape::Box;
  o.center = Vec3(0.7, 0.1, 0);
  o.size = Vec3(0.8, 0.9, 0.7);
  o.solver.tolerance = 1e-11;
  const std::vector<int> region = smoothRegionVertices(input, o);
  const std::vector<int> free = freeOf(*mesh, region);
  const LocalSmoothResult r = localSmooth(input, o);
  EXPECT_GT(r.report.boundaryFixed, 20u);
  EXPECT_EQ(r.report.boundaryFixed + r.report.freeVertices, region.size());
  for (int v : region) {
    const Vec3 d = (mesh->positions()[v] - o.center).cwiseAbs();
    EXPECT_LE((d - 0.5 * o.size).maxCoeff(), 0);
    if (mesh->isBoundaryVertex(v)) {
      EXPECT_EQ(r.field.at(v), input.at(v));  // K = R ∩ ∂M
    }
  }
  EXPECT_LT(harmonicDefect(r.field, free), 1e-9);
}

TEST(LocalSmooth, LinearFieldsAreReproduced) {
  // P1 elements reproduce linear functions, so a linear field is already the harmonic solution
  // for its own boundary values: smoothing must give it back.
  const auto mesh = testing::carvedBall(14);
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    values.push_back(
        Tensor{1 + p.x(), -0.5 + p.y() - p.z(), 0, 0.3 * p.z(), -p.x(), 0.2}.deviator());
  }
  const TensorField input(mesh, values);
  LocalSmoothOptions o;
  o.center = Vec3(-0.2, 0.1, 0);
  o.radius = 0.6;
  o.solver.tolerance = 1e-12;
  const LocalSmoothResult r = localSmooth(input, o);
  double worst = 0;
  for (std::size_t v = 0; v < values.size(); ++v) {
    worst =
        std::max(worst, (r.field.at(static_cast<int>(v)) - input.at(static_cast<int>(v))).norm());
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(LocalSmooth, WarmStartFromAHarmonicFieldNeedsAlmostNoIterations) {
  const auto mesh = testing::carvedBall(14);
  LocalSmoothOptions o;
  o.center = Vec3(0, 0.1, 0);
  o.radius = 0.5;
  o.solver.tolerance = 1e-11;
  const LocalSmoothResult first = localSmooth(wavyField(mesh), o);
  EXPECT_GT(first.report.iterations, 0);
  // Started from the previous solution (relative residual ~1e-11), a looser solve has nothing
  // to do; a cold start (zero guess) would begin at relative residual 1.
  o.solver.tolerance = 1e-8;
  const LocalSmoothResult second = localSmooth(first.field, o);
  EXPECT_EQ(second.report.iterations, 0);
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {  // up to the vec5 round trip
    EXPECT_LT((second.field.at(int(v)) - first.field.at(int(v))).norm(), 1e-14);
  }
}

TEST(LocalSmooth, TraceIsSmoothedAsAHarmonicScalar) {
  const auto mesh = testing::carvedBall(14);
  const TensorField input = wavyField(mesh, 2.0);
  LocalSmoothOptions o;
  o.radius = 0.5;
  o.solver.tolerance = 1e-11;
  const LocalSmoothResult r = localSmooth(input, o);
  const std::vector<int> free = freeOf(*mesh, smoothRegionVertices(input, o));
  // Traceless part harmonic (vec5 drops the trace) and the trace harmonic too.
  EXPECT_LT(harmonicDefect(r.field, free), 1e-9);
  std::vector<Tensor> traces;
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {
    traces.push_back(Tensor::fromVec5({r.field.at(static_cast<int>(v)).trace(), 0, 0, 0, 0}));
  }
  EXPECT_LT(harmonicDefect(TensorField(mesh, traces), free), 1e-9);
  for (int v : free) EXPECT_GT(r.field.at(v).trace(), 1.5);  // kept, not dropped
}

TEST(LocalSmooth, SameResultForOneAndTwoThreads) {
  std::vector<std::vector<Tensor>> results;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const auto mesh = testing::carvedBall(14);
    LocalSmoothOptions o;
    o.center = Vec3(0.1, 0, 0);
    o.radius = 0.55;
    results.push_back(localSmooth(wavyField(mesh), o).field.values());
  }
  EXPECT_EQ(results[0], results[1]);
}

TEST(LocalSmooth, RefusesBadRegions) {
  const auto mesh = testing::carvedBall(10);
  const TensorField field = wavyField(mesh);
  const auto expectError = [&](const LocalSmoothOptions& o, const std::string& text) {
    try {
      localSmooth(field, o);
      ADD_FAILURE() << "no error, expected: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  LocalSmoothOptions o;
  o.center = Vec3(5, 5, 5);
  o.radius = 0.1;
  expectError(o, "the sphere at (5, 5, 5) radius 0.1 contains no mesh vertex");
  o.center = Vec3::Zero();
  o.radius = 0;
  expectError(o, "radius: must be a positive number");
  o.radius = NAN;
  expectError(o, "radius: must be a positive number");
  o.region = SmoothRegionShape::Box;
  o.size = Vec3(1, -1, 1);
  expectError(o, "size: must be a positive number");
  o.size = Vec3(0.5, 0.5, 0.5);
  o.center = Vec3(3, 0, 0);
  expectError(o, "the box at (3, 0, 0) size (0.5, 0.5, 0.5) contains no mesh vertex");
  o.center = Vec3(NAN, 0, 0);
  expectError(o, "center: not finite");
}

}  // namespace
}  // namespace tfd::core
