// Element synthesis on analytic fields over structured box meshes: each element's axes are the
// eigenframe at its centre, sticks sit only in linear regions and leaves only in planar ones,
// no two element boxes overlap (all pairs, independent oracle), the samples keep the metric
// distance and their spacing follows the metric, and the result is the same on 1 and 2 threads.
#include "core/synth/element_synthesis.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <unsupported/Eigen/MatrixFunctions>

#include "core/error.h"
#include "core/synth/spacing_metric.h"
#include "tests/core/synth/synth_test_support.h"

namespace tfd::core {
namespace {

const TensorField& twoRegionField() {
  static const TensorField f =
      test::sampledField(8, Vec3(-1, -1, -1), Vec3(1, 1, 1), test::affineTwoRegionField);
  return f;
}

ElementSynthesisOptions smallOptions() {
  ElementSynthesisOptions o;
  o.size = 0.25;
  o.seed = 3;
  return o;
}

OrientedBox boxOf(const InstancePoint& ip, const ElementShapes& shapes) {
  return {ip.position, rotationOf(ip.orient), ip.scale.cwiseProduct(shapes.of(ip.kind).half)};
}

TEST(ElementSynthesis, AxesAreTheEigenframeAtTheCentreAndKindsFollowTheRegions) {
  const ElementShapes shapes;
  const ElementPlacement placed = placeElements(twoRegionField(), shapes, smallOptions());
  ASSERT_GT(placed.report.lines, 50u) << placed.report.summary();
  ASSERT_GT(placed.report.boxes, 50u) << placed.report.summary();
  EXPECT_EQ(placed.points.points.size(), placed.report.lines + placed.report.boxes);
  for (const InstancePoint& ip : placed.points.points) {
    EXPECT_NEAR(ip.orient.norm(), 1, 1e-12);
    const Mat3 r = rotationOf(ip.orient);
    EXPECT_NEAR(r.determinant(), 1, 1e-9);
    // The field is affine, so its interpolation is the analytic tensor at the centre.
    const Tensor a = test::affineTwoRegionField(ip.position).deviator();
    const EigenDecomposition e = eigenDecompose(a);
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(std::abs(r.col(k).dot(e.vectors.col(k))), 1 - 1e-6)
          << "axis " << k << " at " << ip.position.transpose();
    if (std::abs(e.values[1]) < 1e-9 * a.norm()) continue;  // too close to call
    const TensorType type = classify(a);
    EXPECT_EQ(ip.kind == ElementKind::Line, type == TensorType::Linear)
        << "at " << ip.position.transpose() << ", λ = " << e.values.transpose();
    // A stick lies along e1; a leaf's normal (local z) is e3.
    const int defining = ip.kind == ElementKind::Line ? 0 : 2;
    EXPECT_GT(std::abs(r.col(defining).dot(e.vectors.col(defining))), 1 - 1e-6);
  }
}

TEST(ElementSynthesis, NoTwoElementsOverlapBruteForce) {
  const ElementShapes shapes;
  ElementSynthesisOptions o = smallOptions();
  o.density = 1.6;  // crowded: many candidates collide and must be dropped
  const ElementPlacement placed = placeElements(twoRegionField(), shapes, o);
  ASSERT_GT(placed.report.overlapRejected, 10u) << placed.report.summary();
  const auto& pts = placed.points.points;
  ASSERT_GT(pts.size(), 200u);
  std::vector<OrientedBox> boxes;
  for (const InstancePoint& ip : pts) boxes.push_back(boxOf(ip, shapes));
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      ASSERT_FALSE(test::cornersOverlap(boxes[i], boxes[j])) << "elements " << i << ", " << j;
  // Without rejection the same crowding does make overlapping elements (the check can fail).
  o.rejectOverlaps = false;
  const ElementPlacement crowded = placeElements(twoRegionField(), shapes, o);
  int overlaps = 0;
  const auto& cp = crowded.points.points;
  for (std::size_t i = 0; i < cp.size() && overlaps == 0; ++i)
    for (std::size_t j = i + 1; j < cp.size(); ++j)
      overlaps += test::cornersOverlap(boxOf(cp[i], shapes), boxOf(cp[j], shapes));
  EXPECT_GT(overlaps, 0);
}

TEST(ElementSynthesis, MetricIsTheMatrixExponentialAndContinuousThroughADegeneracy) {
  const SpacingMetric metric(0.1, 0.8, 1.5);
  // Through the L-degenerate tensor diag(2, -1, -1): e2 and e3 swap there, M does not jump.
  auto a = [](double t) { return Tensor{2, -1 + t, -1 - t, 0, 0.3 * t, 0}; };
  Mat3 previous = metric.metric(eigenDecompose(a(-1e-3)));
  for (double t = -1e-3; t <= 1e-3; t += 1e-4) {
    const Mat3 m = metric.metric(eigenDecompose(a(t)));
    const Mat3 expected = (-2 * 0.8 / 1.5 * a(t).matrix()).exp() / (0.1 * 0.1);
    EXPECT_LT((m - expected).norm(), 1e-9 * expected.norm()) << "t = " << t;
    EXPECT_LT((m - previous).norm(), 1e-2 * m.norm()) << "t = " << t;
    EXPECT_NEAR(m.determinant(), std::pow(0.1, -6), 1e-6 * std::pow(0.1, -6));
    previous = m;
  }
}

TEST(ElementSynthesis, SamplesKeepTheirMetricDistance) {
  const ElementShapes shapes;
  ElementSynthesisOptions o = smallOptions();
  o.rejectOverlaps = false;  // every sample an element: the output is the whole sample set
  const ElementPlacement placed = placeElements(twoRegionField(), shapes, o);
  const auto& pts = placed.points.points;
  ASSERT_EQ(pts.size(), placed.report.samples);
  double s = 0;
  for (const Tensor& t : twoRegionField().values()) s += t.deviator().norm() * t.deviator().norm();
  s = std::sqrt(s / double(twoRegionField().values().size()));
  auto metricAt = [&](const Vec3& p) {
    const Mat3 a = test::affineTwoRegionField(p).deviator().matrix();
    return Mat3((-2 * o.anisotropy / s * a).exp() / std::pow(o.size / o.density, 2));
  };
  std::vector<Mat3> m;
  for (const InstancePoint& ip : pts) m.push_back(metricAt(ip.position));
  double closest = 1e300;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const Vec3 d = pts[i].position - pts[j].position;
      closest = std::min(closest, d.dot(0.5 * (m[i] + m[j]) * d));
    }
  EXPECT_GE(closest, 1 - 1e-9);
  EXPECT_LT(closest, 1.2) << "a packing, not a sparse scatter";
}

/// Samples of a constant field A on the box [0, 1]³.
ElementPlacement constantFieldSamples(const Tensor& a, double density, double anisotropy) {
  const TensorField f =
      test::sampledField(4, Vec3::Zero(), Vec3::Ones(), [&](const Vec3&) { return a; });
  ElementSynthesisOptions o;
  o.size = 0.1;
  o.density = density;
  o.anisotropy = anisotropy;
  o.rejectOverlaps = false;
  return placeElements(f, ElementShapes{}, o);
}

TEST(ElementSynthesis, SampleDensityFollowsTheMetric) {
  const Tensor linear{2, -1, -1, 0, 0, 0};  // L-degenerate: e1 = x
  // The metric's volume does not depend on A, so the count depends on density alone: about
  // density³ more samples, and about as many for an anisotropic as for an isotropic metric.
  const double n1 = double(constantFieldSamples(linear, 1, 1).points.points.size());
  const double n2 = double(constantFieldSamples(linear, 2, 1).points.points.size());
  const double iso = double(constantFieldSamples(linear, 1, 0).points.points.size());
  EXPECT_NEAR(n2 / n1, 8, 8 * 0.2) << n1 << " then " << n2;
  EXPECT_NEAR(n1 / iso, 1, 0.2) << n1 << " anisotropic, " << iso << " isotropic";
  // The shape: neighbour offsets, divided by the spacing h_k along each axis, are as long
  // along x as across (the metric's unit ball), while in world units x is stretched by
  // h_x / h_y = exp(κ (λ1 - λ2) / s) = exp(3 / √6).
  const auto pts = constantFieldSamples(linear, 2, 1).points.points;
  const double s = linear.norm();
  const Vec3 h = 0.05 * Vec3(std::exp(2 / s), std::exp(-1 / s), std::exp(-1 / s));
  Vec3 sum = Vec3::Zero();
  int pairs = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const Vec3 d = (pts[i].position - pts[j].position).cwiseQuotient(h);
      if (d.norm() < 1.6) sum += d.cwiseAbs2(), ++pairs;
    }
  ASSERT_GT(pairs, 1000);
  const Vec3 mean = sum / pairs;
  EXPECT_NEAR(mean.x() / mean.y(), 1, 0.15) << mean.transpose();
  EXPECT_NEAR(mean.x() / mean.z(), 1, 0.15) << mean.transpose();
}

TEST(ElementSynthesis, SameResultOnOneAndTwoThreadsAndSeedsMatter) {
  if (tbb::this_task_arena::max_concurrency() < 2) GTEST_SKIP() << "needs two threads";
  const ElementShapes shapes;
  auto run = [&](int threads, std::uint64_t seed) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    ElementSynthesisOptions o = smallOptions();
    o.seed = seed;
    ElementPlacement p = placeElements(twoRegionField(), shapes, o);
    return std::make_pair(p.points, instanceElements(p.points, shapes));
  };
  const auto one = run(1, 3), two = run(2, 3), other = run(2, 4);
  ASSERT_EQ(one.first.points.size(), two.first.points.size());
  for (std::size_t i = 0; i < one.first.points.size(); ++i) {
    const InstancePoint &a = one.first.points[i], &b = two.first.points[i];
    ASSERT_EQ(std::memcmp(a.position.data(), b.position.data(), sizeof(double) * 3), 0);
    ASSERT_EQ(std::memcmp(a.orient.data(), b.orient.data(), sizeof(double) * 4), 0);
    ASSERT_EQ(a.kind, b.kind);
  }
  ASSERT_EQ(one.second.positions.size(), two.second.positions.size());
  EXPECT_EQ(std::memcmp(one.second.positions.data(), two.second.positions.data(),
                        sizeof(Vec3) * one.second.positions.size()),
            0);
  EXPECT_EQ(one.second.triangles, two.second.triangles);
  EXPECT_NE(one.first.points.front().position, other.first.points.front().position);
}

TEST(ElementSynthesis, InstancedMeshPlacesEachShapeByItsPoint) {
  const ElementShapes shapes;
  InstancePoints pts;
  InstancePoint ip;
  ip.position = Vec3(1, 2, 3);
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  const Eigen::Quaterniond q(r);
  ip.orient = {q.w(), q.x(), q.y(), q.z()};
  ip.scale = Vec3::Constant(0.5);
  ip.kind = ElementKind::Box;
  pts.points = {ip};
  const SurfaceMesh m = instanceElements(pts, shapes);
  ASSERT_EQ(m.positions.size(), shapes.box.mesh.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v)
    EXPECT_LT((m.positions[v] - (ip.position + 0.5 * r * shapes.box.mesh.positions[v])).norm(),
              1e-12);
}

/// Each undirected edge used by exactly two triangles, once in each direction, and a positive
/// enclosed volume: a closed, consistently outward-oriented surface.
void expectClosedOutward(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << e.first << "-" << e.second;
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << e.first << "-" << e.second;
  }
  double volume = 0;
  for (const auto& t : m.triangles)
    volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
  EXPECT_GT(volume, 0);
}

TEST(ElementSynthesis, BuiltInShapesAreClosedUnitElementsWithBoxSymmetry) {
  const ElementShapes shapes;
  expectClosedOutward(shapes.line.mesh);
  expectClosedOutward(shapes.box.mesh);
  EXPECT_NEAR(shapes.line.half.x(), 0.5, 1e-12);
  EXPECT_NEAR(shapes.box.half.x(), 0.5, 1e-12);
  EXPECT_LT(shapes.line.half.y(), 0.05);
  EXPECT_LT(shapes.box.half.z(), 0.05);
  EXPECT_GT(shapes.box.half.y(), 0.15);
  // Box symmetry: a half-turn about each axis maps the leaf's vertex set onto itself, so the
  // eigenvectors' signs do not show.
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 flip = -Vec3::Ones();
    flip[axis] = 1;
    for (const Vec3& p : shapes.box.mesh.positions) {
      double nearest = 1e300;
      for (const Vec3& q : shapes.box.mesh.positions)
        nearest = std::min(nearest, (q - p.cwiseProduct(flip)).norm());
      EXPECT_LT(nearest, 1e-12) << "axis " << axis;
    }
  }
}

TEST(ElementSynthesis, UserElementsAreRecentredAndScaledToUnitLength) {
  SurfaceMesh m;
  m.positions = {Vec3(1, 1, 1), Vec3(5, 1, 1), Vec3(1, 3, 1), Vec3(1, 1, 2)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const ElementShape e = normalizedElement(m, "test");
  EXPECT_LT((e.half - Vec3(0.5, 0.25, 0.125)).norm(), 1e-15);
  EXPECT_LT((e.mesh.positions[0] - Vec3(-0.5, -0.25, -0.125)).norm(), 1e-15);
  EXPECT_THROW(normalizedElement(SurfaceMesh{}, "test"), Error);
}

TEST(ElementSynthesis, BadOptionsAreRefused) {
  ElementSynthesisOptions o = smallOptions();
  o.density = 0;
  EXPECT_THROW(placeElements(twoRegionField(), ElementShapes{}, o), Error);
  o = smallOptions();
  o.size = -1;
  EXPECT_THROW(placeElements(twoRegionField(), ElementShapes{}, o), Error);
}

}  // namespace
}  // namespace tfd::core
