// Extraction on linear fields A0 + x Gx + y Gy + z Gz: PL interpolation reproduces them exactly
// on any mesh, and their degenerate set is known in closed form (algorithms note §2.2): with N
// the normal of span{A0, Gx, Gy, Gz}, every v with vᵀNv = 0 gives b(v) = α A0 + Σ β_k G_k and
// the point p = β/α, of type sign(α). The truth here is computed independently of the
// extractor (SVD null space and a least-squares solve per point).
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cmath>
#include <numbers>
#include <random>

#include "core/topology/extract_degenerate_curves.h"
#include "core/topology/traceless5.h"
#include "tests/core/topology/topology_test_support.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core::topology {
namespace {

using testing::LinearField;

struct ExactCurve {
  LinearField field;
  Eigen::Matrix<double, 5, 4> m;
  Mat3 n;
  explicit ExactCurve(const LinearField& f) : field(f) {
    m << toVec5(f.a0), toVec5(f.g[0]), toVec5(f.g[1]), toVec5(f.g[2]);
    const Eigen::JacobiSVD<Eigen::Matrix<double, 5, 5>> svd(
        (Eigen::Matrix<double, 5, 5>() << m, Vec5::Zero()).finished(), Eigen::ComputeFullU);
    n = matrixOf(svd.matrixU().col(4));
  }
  /// The exact curve point with non-degenerate eigenvector v (α, β from least squares).
  bool point(const Vec3& v, Vec3& p, double& sigma) const {
    const Eigen::Vector4d x = m.colPivHouseholderQr().solve(veronese(v));
    if (std::abs(x[0]) < 1e-12) return false;
    p = Vec3(x[1], x[2], x[3]) / x[0];
    sigma = 1 / x[0];
    return true;
  }
  /// cos(t, e) sign of the exact δ at eigenvector e.
  double cosine(const Vec3& e) const {
    Vec3 u, w;
    completeFrame(e.normalized(), u, w);
    Vec3 ga, gb;
    for (int k = 0; k < 3; ++k) {
      const Mat3 g = field.g[k].matrix();
      ga[k] = 0.5 * (u.dot(g * u) - w.dot(g * w));
      gb[k] = u.dot(g * w);
    }
    const Vec3 t = ga.cross(gb);
    return t.normalized().dot(e.normalized());
  }
};

/// Dense sampling of the exact curve: the number of its connected pieces inside the box
/// (shrunk by `margin`), and the sample points inside.
int piecesInside(const ExactCurve& exact, double lo, double hi, double margin,
                 std::vector<Vec3>* inside) {
  // Parameterise the conic vᵀNv = 0 by its eigen-frame (independent of the extractor's chart).
  const Eigen::SelfAdjointEigenSolver<Mat3> es(exact.n);
  Vec3 l = es.eigenvalues();  // ascending
  Mat3 q = es.eigenvectors();
  // Axis: the eigenvalue whose sign is alone.
  int axis = l[1] > 0 ? 0 : 2;
  int i1 = axis == 0 ? 1 : 0, i2 = axis == 0 ? 2 : 1;
  const double a = std::sqrt(-l[axis] / l[i1]), b = std::sqrt(-l[axis] / l[i2]);
  constexpr int kSamples = 200000;
  std::vector<char> in(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double t = 2 * std::numbers::pi * i / kSamples;
    const Vec3 v = q.col(axis) + a * std::cos(t) * q.col(i1) + b * std::sin(t) * q.col(i2);
    Vec3 p;
    double sigma;
    in[i] = exact.point(v.normalized(), p, sigma) && (p.array() > lo + margin).all() &&
            (p.array() < hi - margin).all();
    if (in[i] && inside) inside->push_back(p);
  }
  int pieces = 0;
  for (int i = 0; i < kSamples; ++i) pieces += in[i] && !in[(i + kSamples - 1) % kSamples];
  if (pieces == 0 && in[0]) pieces = 1;  // a closed curve entirely inside (impossible here)
  return pieces;
}

double distanceToCurves(const DegenerateCurves& curves, const Vec3& p) {
  const auto pick = curves.pick(p);
  return pick ? pick->distance : 1e300;
}

TEST(TopologyLinearField, PointsLieExactlyOnTheCurveWithTheRightTypeAndPattern) {
  int curvesSeen = 0, pointsChecked = 0, transitions = 0, wedges = 0, trisectors = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 rng(seed);
    const LinearField lf = testing::randomLinearField(rng);
    const ExactCurve exact(lf);
    const auto mesh = testing::jitteredBox(5, -1, 1, 0.15, seed);
    const TensorField field = testing::sampleField(mesh, lf);
    const DegenerateCurves curves = extractDegenerateCurves(field);
    EXPECT_TRUE(curves.warnings().empty()) << "seed " << seed << ": " << curves.warnings()[0];
    EXPECT_EQ(curves.diagnostics().rounds, 0) << "a generic field needs no fallback";
    const double domain = 2;
    for (const DegenerateCurve& c : curves.curves()) {
      ++curvesSeen;
      EXPECT_FALSE(c.closed) << "a linear field has no bounded loop (note §2.2 fact 3)";
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        Vec3 p;
        double sigma;
        ASSERT_TRUE(exact.point(c.eigenvectors[i], p, sigma));
        EXPECT_LT((p - c.points[i]).norm(), 1e-9 * domain) << "seed " << seed << " point " << i;
        EXPECT_LT(testing::scaledDiscriminant(lf(c.points[i])), 1e-18);
        EXPECT_EQ(sigma > 0, c.type == DegenerateType::Linear);
        const double cosine = exact.cosine(c.eigenvectors[i]);
        if (c.patterns[i] == DegeneratePattern::Transition) {
          ++transitions;
          if (c.sources[i].kind == PointSource::Kind::Tet) {
            EXPECT_LT(std::abs(cosine), 1e-9);
          }
        } else if (std::abs(cosine) > 1e-9) {
          EXPECT_EQ(cosine > 0, c.patterns[i] == DegeneratePattern::Wedge) << "seed " << seed;
          ++(cosine > 0 ? wedges : trisectors);
        }
        // Tangent of the exact curve: the same formula with exact gradients.
        ++pointsChecked;
      }
    }
    // Topology: as many curves as the exact curve has pieces inside the box, and every dense
    // sample of the exact curve lies near the extracted polylines.
    std::vector<Vec3> inside;
    const int pieces = piecesInside(exact, -1, 1, 0, &inside);
    EXPECT_EQ(int(curves.size()), pieces) << "seed " << seed;
    const double h = mesh->meanEdgeLength();
    double worst = 0;
    for (std::size_t i = 0; i < inside.size(); i += 50)
      worst = std::max(worst, distanceToCurves(curves, inside[i]));
    EXPECT_LT(worst, 0.25 * h) << "seed " << seed;
  }
  EXPECT_GT(curvesSeen, 12);
  EXPECT_GT(pointsChecked, 300);
  EXPECT_GT(wedges, 50);
  EXPECT_GT(trisectors, 50);
  std::printf("linear fields: %d curves, %d points, %d transition points\n", curvesSeen,
              pointsChecked, transitions);
}

TEST(TopologyLinearField, ExactOnABallMesh) {
  const auto mesh = test::mappedBall(15);  // curved boundary, tets of varying shape
  int points = 0;
  for (unsigned seed = 50; seed < 54; ++seed) {
    std::mt19937_64 rng(seed);
    const LinearField lf = testing::randomLinearField(rng);
    const ExactCurve exact(lf);
    const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, lf));
    EXPECT_TRUE(curves.warnings().empty()) << curves.warnings()[0];
    for (const DegenerateCurve& c : curves.curves()) {
      EXPECT_FALSE(c.closed);
      // Open curves end on the sphere.
      EXPECT_NEAR(c.points.front().norm(), 1, 0.02);
      EXPECT_NEAR(c.points.back().norm(), 1, 0.02);
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        Vec3 p;
        double sigma;
        ASSERT_TRUE(exact.point(c.eigenvectors[i], p, sigma));
        EXPECT_LT((p - c.points[i]).norm(), 2e-9);
        EXPECT_EQ(sigma > 0, c.type == DegenerateType::Linear);
        ++points;
      }
    }
  }
  EXPECT_GT(points, 100);
}

TEST(TopologyLinearField, TransitionPointsAreWhereTheTangentIsPerpendicular) {
  int found = 0;
  for (unsigned seed = 20; seed < 40 && found < 5; ++seed) {
    std::mt19937_64 rng(seed);
    const LinearField lf = testing::randomLinearField(rng);
    const ExactCurve exact(lf);
    const auto mesh = testing::jitteredBox(4, -1, 1, 0.15, seed);
    const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, lf));
    for (const DegenerateCurve& c : curves.curves()) {
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (c.patterns[i] != DegeneratePattern::Transition ||
            c.sources[i].kind != PointSource::Kind::Tet)
          continue;
        // At a transition point the tangent is perpendicular to the eigenvector and the
        // pattern changes between its neighbours.
        EXPECT_LT(std::abs(c.tangents[i].dot(c.eigenvectors[i])), 1e-8);
        EXPECT_NEAR(c.tangents[i].norm(), 1, 1e-12);
        if (i > 0 && i + 1 < c.points.size() &&
            c.patterns[i - 1] != DegeneratePattern::Transition &&
            c.patterns[i + 1] != DegeneratePattern::Transition) {
          EXPECT_NE(c.patterns[i - 1], c.patterns[i + 1]);
        }
        ++found;
      }
    }
  }
  EXPECT_GE(found, 5);
}

TEST(TopologyLinearField, TangentsFollowTheCurve) {
  std::mt19937_64 rng(7);
  const LinearField lf = testing::randomLinearField(rng);
  const auto mesh = testing::jitteredBox(6, -1, 1, 0.15, 7);
  ExtractOptions options;
  options.arcSamples = 4;
  const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, lf), options);
  ASSERT_FALSE(curves.empty());
  int checked = 0;
  for (const DegenerateCurve& c : curves.curves()) {
    for (std::size_t i = 1; i + 1 < c.points.size(); ++i) {
      const Vec3 chord = c.points[i + 1] - c.points[i - 1];
      if (chord.norm() < 1e-6) continue;
      EXPECT_GT(c.tangents[i].dot(chord.normalized()), 0.8) << "point " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30);
}

}  // namespace
}  // namespace tfd::core::topology
