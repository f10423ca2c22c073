// Face solver and face pre-filters: exact degenerate points on a triangle of a PL traceless
// field, checked against the algebra and against a brute-force search.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <random>

#include "core/topology/face_prefilter.h"
#include "core/topology/face_solver.h"
#include "core/topology/traceless5.h"
#include "core/topology/trig_roots.h"
#include "core/topology/zheng_pang.h"
#include "tests/core/topology/topology_test_support.h"

namespace tfd::core::topology {
namespace {

using testing::bruteForceFacePoints;
using testing::randomTraceless;

Tensor at(const Tensor& a, const Tensor& b, const Tensor& c, const Vec3& bary) {
  return bary[0] * a + bary[1] * b + bary[2] * c;
}

TEST(TopologyAlgebra, VeroneseAndBasisAgreeWithTensor) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 50; ++i) {
    const Tensor t = randomTraceless(rng);
    const auto v5 = t.vec5();
    const Vec5 mine = toVec5(t);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(mine[k], v5[k], 1e-14);
    EXPECT_LT((matrixOf(mine) - t.matrix()).norm(), 1e-14);
    const Vec3 v = Vec3::Random();
    const Mat3 b = v * v.transpose() - v.squaredNorm() / 3 * Mat3::Identity();
    EXPECT_LT((veronese(v) - toVec5(b)).norm(), 1e-14);
    // ⟨N, b(v)⟩ = vᵀNv for traceless N.
    EXPECT_NEAR(mine.dot(veronese(v)), v.dot(t.matrix() * v), 1e-12);
  }
}

TEST(TopologyAlgebra, ZhengPangSumOfSquaresIsTheDiscriminant) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 100; ++i) {
    const Tensor t = randomTraceless(rng);
    const double d = discriminant(t);
    EXPECT_NEAR(zhengPangDiscriminant(zhengPangFunctions(t)), d, 1e-11 * std::max(1.0, d));
  }
  // Degenerate tensors σ b(v) + μ I make all seven vanish.
  for (int i = 0; i < 100; ++i) {
    const Vec3 v = Vec3::Random().normalized();
    const Mat3 m = 1.7 * (v * v.transpose()) + 0.3 * Mat3::Identity();
    for (double f : zhengPangFunctions(Tensor::fromMatrix(m))) EXPECT_NEAR(f, 0, 1e-14);
  }
}

TEST(TopologyTrigRoots, QuarticRootsFromKnownFactors) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 2000; ++i) {
    // (x − r1)(x − r2)(x² + p x + q) with q > p²/4 (no real roots) or two more real roots.
    std::vector<double> real = {u(rng), u(rng)};
    double quad[3];
    if (i % 2 == 0) {
      const double p = u(rng), q = p * p / 4 + std::abs(u(rng)) + 0.1;
      quad[0] = q, quad[1] = p, quad[2] = 1;
    } else {
      const double r3 = u(rng), r4 = u(rng);
      real.push_back(r3), real.push_back(r4);
      quad[0] = r3 * r4, quad[1] = -(r3 + r4), quad[2] = 1;
    }
    const double r1 = real[0], r2 = real[1];
    const double lin[3] = {r1 * r2, -(r1 + r2), 1};
    double c[5] = {0, 0, 0, 0, 0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) c[a + b] += lin[a] * quad[b];
    const double lead = u(rng) + 4;
    for (double& v : c) v *= lead;
    double roots[4];
    bool nearDouble[4];
    const int n = quarticRealRoots(c, roots, nearDouble);
    std::sort(real.begin(), real.end());
    bool close = false;
    for (std::size_t k = 1; k < real.size(); ++k) close = close || real[k] - real[k - 1] < 1e-3;
    if (close) continue;  // near-double pairs are covered below
    ASSERT_EQ(n, int(real.size())) << "case " << i;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(roots[k], real[k], 1e-9 * (1 + std::abs(real[k])));
      EXPECT_FALSE(nearDouble[k]);
    }
  }
}

TEST(TopologyTrigRoots, GrazingRootIsReportedAsNearDouble) {
  // (x − 1)² (x² + 1) + tiny: a double root pushed off the axis by 1e-12.
  const double c[5] = {1 + 1e-12, -2, 2, -2, 1};
  double roots[4];
  bool nearDouble[4];
  const int n = quarticRealRoots(c, roots, nearDouble);
  ASSERT_EQ(n, 1);
  EXPECT_TRUE(nearDouble[0]);
  EXPECT_NEAR(roots[0], 1, 1e-5);
}

TEST(TopologyTrigRoots, TrigonometricRootsIncludingThetaPi) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 500; ++i) {
    double a0 = u(rng), a1 = u(rng), b1 = u(rng), a2 = u(rng), b2 = u(rng);
    if (i % 5 == 0) a0 = a1 - a2;  // θ = π is a root: the plain tan(θ/2) map loses it
    std::array<TrigRoot, 4> roots;
    const int n = trigQuadraticRoots(a0, a1, b1, a2, b2, roots);
    const auto g = [&](double t) {
      return a0 + a1 * std::cos(t) + b1 * std::sin(t) + a2 * std::cos(2 * t) + b2 * std::sin(2 * t);
    };
    // Every root is a root, and a dense scan finds no sign change that is not near a root.
    for (int k = 0; k < n; ++k) EXPECT_LT(std::abs(g(roots[k].theta)), 1e-12);
    constexpr int kScan = 4000;
    for (int s = 0; s < kScan; ++s) {
      const double t0 = 2 * std::numbers::pi * s / kScan,
                   t1 = 2 * std::numbers::pi * (s + 1) / kScan;
      if ((g(t0) > 0) == (g(t1) > 0)) continue;
      bool found = false;
      for (int k = 0; k < n; ++k) {
        const double d = std::remainder(roots[k].theta - 0.5 * (t0 + t1), 2 * std::numbers::pi);
        found = found || std::abs(d) < 2e-3;
      }
      EXPECT_TRUE(found) << "case " << i << " sign change at " << t0;
    }
  }
}

TEST(TopologyFaceSolver, PointsAreDegenerateWithCorrectTypeAndEigenvector) {
  std::mt19937_64 rng(3);
  int points = 0;
  for (int face = 0; face < 400; ++face) {
    const Tensor a = randomTraceless(rng), b = randomTraceless(rng), c = randomTraceless(rng);
    const FaceSolution s = solveFace(a, b, c);
    EXPECT_EQ(s.flags & kFaceNeedsFallback, 0u);
    for (int k = 0; k < s.count; ++k) {
      const FacePoint& p = s.points[k];
      EXPECT_NEAR(p.barycentric.sum(), 1, 1e-14);
      EXPECT_GE(p.barycentric.minCoeff(), -1e-10);
      const Tensor t = at(a, b, c, p.barycentric);
      EXPECT_LT(testing::scaledDiscriminant(t), 1e-24);
      // σ b(v) reproduces the tensor (σ in units of the face scale).
      const double scale = std::max({a.norm(), b.norm(), c.norm()});
      EXPECT_LT((toVec5(t) / scale - p.sigma * veronese(p.eigenvector)).norm(), 1e-13);
      const TensorType type = classify(t, 1e-9);
      EXPECT_EQ(type, p.sigma > 0 ? TensorType::Linear : TensorType::Planar);
      ++points;
    }
  }
  EXPECT_GT(points, 50);
}

TEST(TopologyFaceSolver, FindsEveryPointTheBruteForceSearchFinds) {
  std::mt19937_64 rng(4);
  int compared = 0, total = 0;
  for (int face = 0; face < 240; ++face) {
    // Random faces of a smooth field: corners close to each other, so points are rare but
    // the pencil is poorly conditioned like on a real mesh.
    const Tensor base = randomTraceless(rng);
    const double spread = face % 2 == 0 ? 1.0 : 0.4;
    const Tensor a = base + randomTraceless(rng, spread), b = base + randomTraceless(rng, spread),
                 c = base + randomTraceless(rng, spread);
    const FaceSolution s = solveFace(a, b, c);
    const auto truth = bruteForceFacePoints(a, b, c);
    // Brute force may miss points but never invents them; the solver must find each one.
    for (const Vec3& t : truth) {
      bool found = false;
      for (int k = 0; k < s.count; ++k)
        found = found || (s.points[k].barycentric - t).norm() < 1e-6;
      EXPECT_TRUE(found) << "face " << face << " misses brute-force point " << t.transpose();
    }
    EXPECT_GE(s.count, int(truth.size()));
    compared += int(truth.size());
    total += s.count;
  }
  EXPECT_GT(compared, 20);
  EXPECT_EQ(compared, total) << "solver points that brute force did not confirm";
}

TEST(TopologyFaceSolver, BlockDiagonalFieldIsReportedNotGuessed) {
  // T13 = T23 = 0 on every corner (the paper's default design elements): the conics share the
  // component v_z = 0, a whole curve of the face plane is degenerate.
  const Tensor a{0.3, -0.9, 0.6, 0.1, 0, 0}, b{-0.5, -0.2, 0.7, 0.4, 0, 0},
      c{0.1, 0.2, -0.3, -0.6, 0, 0};
  const FaceSolution s = solveFace(a, b, c);
  EXPECT_TRUE(s.flags & kFaceDegeneratePencil);
  EXPECT_EQ(s.count, 0);
}

TEST(TopologyFaceSolver, ConstantAndZeroFacesAreFlagged) {
  const Tensor a{1, -0.5, -0.5, 0.2, 0.1, 0};
  EXPECT_TRUE(solveFace(a, a, a).flags & kFaceRankDeficient);
  EXPECT_TRUE(solveFace(Tensor{}, Tensor{}, Tensor{}).flags & kFaceZero);
}

TEST(TopologyFaceSolver, PerturbedBlockDiagonalFaceIsSolvedAccurately) {
  // After a 1e-7 perturbation the pencil is generic but badly conditioned; every point the
  // brute force finds must still be found, and be exact.
  std::mt19937_64 rng(5);
  int found = 0;
  for (int face = 0; face < 60; ++face) {
    // Block-diagonal field x-linear around the degenerate axis x = y = 0: A = diag-block.
    const auto blockField = [](double x, double y) { return Tensor{x - 1, -x - 1, 2, y, 0, 0}; };
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    const Vec3 pa(u(rng), u(rng), 0), pb(u(rng), u(rng), 0), pc(u(rng), u(rng), 0);
    const Tensor a = blockField(pa.x(), pa.y()) + randomTraceless(rng, 1e-7);
    const Tensor b = blockField(pb.x(), pb.y()) + randomTraceless(rng, 1e-7);
    const Tensor c = blockField(pc.x(), pc.y()) + randomTraceless(rng, 1e-7);
    const FaceSolution s = solveFace(a, b, c);
    for (int k = 0; k < s.count; ++k) {
      EXPECT_LT(testing::scaledDiscriminant(at(a, b, c, s.points[k].barycentric)), 1e-24);
    }
    const auto truth = bruteForceFacePoints(a, b, c);
    for (const Vec3& t : truth) {
      bool hit = false;
      for (int k = 0; k < s.count; ++k) hit = hit || (s.points[k].barycentric - t).norm() < 1e-6;
      EXPECT_TRUE(hit) << "face " << face;
    }
    // The axis x = y = 0 crosses the triangle iff the origin is inside it.
    const Eigen::Matrix2d e{{pb.x() - pa.x(), pc.x() - pa.x()}, {pb.y() - pa.y(), pc.y() - pa.y()}};
    const Eigen::Vector2d st = e.inverse() * Eigen::Vector2d(-pa.x(), -pa.y());
    const bool inside = st.minCoeff() > 1e-3 && st.sum() < 1 - 1e-3;
    if (inside) {
      bool axis = false;
      for (int k = 0; k < s.count; ++k) {
        const Vec3 bary = s.points[k].barycentric;
        const Vec3 p = bary[0] * pa + bary[1] * pb + bary[2] * pc;
        axis = axis || (p.head<2>().norm() < 1e-5 && s.points[k].sigma > 0);
      }
      EXPECT_TRUE(axis) << "face " << face << " misses the L axis";
      ++found;
    }
  }
  EXPECT_GT(found, 3);
}

TEST(TopologyFacePrefilter, NeverExcludesAFaceWithAPoint) {
  std::mt19937_64 rng(6);
  int excludedGap = 0, excludedBernstein = 0, withPoints = 0;
  for (int face = 0; face < 3000; ++face) {
    const Tensor base = randomTraceless(rng);
    const double spread = (face % 4 + 1) * 0.1;
    const Tensor a = base + randomTraceless(rng, spread), b = base + randomTraceless(rng, spread),
                 c = base + randomTraceless(rng, spread);
    const FaceSolution s = solveFace(a, b, c);
    const Tensor* corners[3] = {&a, &b, &c};
    const double gaps[3] = {degeneracyDistanceLowerBound(a), degeneracyDistanceLowerBound(b),
                            degeneracyDistanceLowerBound(c)};
    const bool gap = gapExcludesFace(corners, gaps);
    const bool bern = bernsteinExcludesFace(a, b, c);
    if (s.count > 0) {
      ++withPoints;
      EXPECT_FALSE(gap) << "face " << face;
      EXPECT_FALSE(bern) << "face " << face;
    }
    excludedGap += gap;
    excludedBernstein += bern;
  }
  EXPECT_GT(withPoints, 50);
  std::printf("faces with points %d, culled by gap %d, by Bernstein %d of 3000\n", withPoints,
              excludedGap, excludedBernstein);
  // Both tests must do real work on smooth-looking data.
  EXPECT_GT(excludedGap, 300);
  EXPECT_GT(excludedBernstein, 1000);
}

TEST(TopologyFacePrefilter, DistanceBoundIsBelowTheTrueDistance) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Tensor t = randomTraceless(rng);
    const EigenDecomposition e = eigenDecompose(t);
    const double exact =
        std::min(e.values[0] - e.values[1], e.values[1] - e.values[2]) / std::sqrt(2.0);
    const double bound = degeneracyDistanceLowerBound(t);
    EXPECT_LE(bound, exact);
    EXPECT_GT(bound, exact - 1e-6 * t.norm());
    // A degenerate tensor at that distance exists: average the closest pair.
    Vec3 l = e.values;
    if (l[0] - l[1] < l[1] - l[2])
      l[0] = l[1] = (l[0] + l[1]) / 2;
    else
      l[1] = l[2] = (l[1] + l[2]) / 2;
    const Mat3 d = e.vectors * l.asDiagonal() * e.vectors.transpose();
    EXPECT_NEAR((d - t.matrix()).norm(), exact, 1e-12);
    EXPECT_LT(testing::scaledDiscriminant(Tensor::fromMatrix(d)), 1e-20);
  }
}

}  // namespace
}  // namespace tfd::core::topology
