// Discrete parallel transport and Bishop frames (core/design/parallel_transport.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/design/parallel_transport.h"
#include "core/design/spline.h"
#include "core/error.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

/// Wraps an angle to (−π, π].
double wrap(double a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a <= 0) a += 2 * kPi;
  return a - kPi;
}

/// Signed area of the spherical polygon t0 → t1 → … → t0, by a fan of spherical triangles from
/// t0 (Van Oosterom–Strackee solid angle of each triangle). Independent of parallel transport.
double fanSolidAngle(const std::vector<Vec3>& t) {
  double sum = 0;
  const Vec3& a = t[0];
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    const Vec3 &b = t[i], &c = t[i + 1];
    sum += 2 * std::atan2(a.dot(b.cross(c)), 1 + a.dot(b) + b.dot(c) + c.dot(a));
  }
  return sum;
}

void expectFrame(const Mat3& f, const Vec3& tangent) {
  EXPECT_LT((f.transpose() * f - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_NEAR(f.determinant(), 1.0, 1e-13);
  EXPECT_LT((f.col(0) - tangent.normalized()).norm(), 1e-14);
}

TEST(ParallelTransport, MinimalRotationMapsTangentAndFixesTheBinormal) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 200; ++k) {
    const Vec3 a = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 b = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Mat3 r = transportRotation(a, b);
    EXPECT_LT((r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(r.determinant(), 1, 1e-12);
    EXPECT_LT((r * a - b).norm(), 1e-12);
    const Vec3 axis = a.cross(b).normalized();
    EXPECT_LT((r * axis - axis).norm(), 1e-12);
    // Rotation angle = angle between a and b (trace = 1 + 2 cos φ).
    EXPECT_NEAR((r.trace() - 1) / 2, a.dot(b), 1e-12);
  }
  EXPECT_LT((transportRotation(Vec3::UnitX(), Vec3::UnitX()) - Mat3::Identity()).norm(), 1e-16);
  EXPECT_THROW(transportRotation(Vec3::UnitX(), -Vec3::UnitX()), Error);
}

TEST(ParallelTransport, FramesAreOrthonormalRightHandedTangentFirst) {
  const Spline s({{0, 0, 0}, {1, 0.5, 0.2}, {1.5, 1.5, -0.3}, {0.5, 2.5, 0.4}, {-1, 2, 1}}, false);
  const CurveSamples c = s.sample(0.05);
  const BishopFrames b = bishopFrames(c.tangents, false);
  ASSERT_EQ(b.frames.size(), c.tangents.size());
  for (std::size_t i = 0; i < c.tangents.size(); ++i) expectFrame(b.frames[i], c.tangents[i]);
  // A given initial normal is honoured after projection.
  BishopOptions o;
  o.initialNormal = Vec3(0.3, 0.1, 5);
  const BishopFrames b2 = bishopFrames(c.tangents, false, o);
  const Vec3 t0 = c.tangents[0];
  const Vec3 expected = (o.initialNormal - o.initialNormal.dot(t0) * t0).normalized();
  EXPECT_LT((b2.frames[0].col(1) - expected).norm(), 1e-14);
}

TEST(ParallelTransport, NoTwistOnAPlanarCurve) {
  // A planar, wiggly curve in the plane with normal n: the Bishop frame never leaves the plane,
  // so a normal started on n stays exactly n, and one started in the plane stays in it.
  const Vec3 n = Vec3(1, 2, 2).normalized();
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  std::vector<Vec3> pts;
  for (int i = 0; i < 9; ++i) {
    const double x = 0.4 * i, y = std::sin(1.3 * i) + 0.2 * i;
    pts.push_back(x * e1 + y * e2);
  }
  const CurveSamples c = Spline(pts, false).sample(0.02);
  BishopOptions o;
  o.initialNormal = n;
  const BishopFrames b = bishopFrames(c.tangents, false, o);
  for (std::size_t i = 0; i < b.frames.size(); ++i) {
    expectFrame(b.frames[i], c.tangents[i]);
    EXPECT_LT((b.frames[i].col(1) - n).norm(), 1e-12) << i;
  }
  o.initialNormal = e1 + e2;
  for (const Mat3& f : bishopFrames(c.tangents, false, o).frames) {
    EXPECT_LT(std::abs(f.col(1).dot(n)), 1e-12);
    EXPECT_LT((f.col(2).cross(n)).norm(), 1e-12);  // v = ±n
  }
}

TEST(ParallelTransport, BishopNormalTurnsAgainstTorsionOnAHelix) {
  // Helix r(s) = (a cos(s/c), a sin(s/c), b s/c), c = √(a² + b²): torsion τ = b/c². Writing the
  // Bishop normal as u = cos θ N + sin θ B in the Frenet frame, twist-freeness means θ' = −τ.
  const double a = 1.0, b = 0.4, c = std::sqrt(a * a + b * b), tau = b / (c * c);
  const int n = 4000;
  const double length = 12.0, h = length / n;
  std::vector<Vec3> tangents, normals;
  for (int i = 0; i <= n; ++i) {
    const double s = i * h, w = s / c;
    tangents.push_back(Vec3(-a * std::sin(w), a * std::cos(w), b) / c);
    normals.push_back(Vec3(-std::cos(w), -std::sin(w), 0));  // Frenet N
  }
  BishopOptions o;
  o.initialNormal = normals[0];
  const BishopFrames f = bishopFrames(tangents, false, o);
  for (int i = 0; i <= n; i += 250) {
    const double theta = signedAngle(normals[i], f.frames[i].col(1), tangents[i]);
    EXPECT_NEAR(theta, wrap(-tau * i * h), 1e-5) << "s = " << i * h;
  }
}

TEST(ParallelTransport, HolonomyOfACircleOfLatitudeIsTheCapArea) {
  // Tangents running once around the circle of colatitude α: the indicatrix bounds a cap of
  // area 2π(1 − cos α), so the holonomy is that modulo 2π, i.e. −2π cos α.
  for (double alpha : {0.3, 0.9, 1.4, 2.0}) {
    std::vector<Vec3> t;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * kPi * i / n;
      t.push_back(
          Vec3(std::sin(alpha) * std::cos(phi), std::sin(alpha) * std::sin(phi), std::cos(alpha)));
    }
    BishopOptions o;
    o.distributeHolonomy = false;
    const BishopFrames f = bishopFrames(t, true, o);
    EXPECT_NEAR(f.holonomy, wrap(2 * kPi * (1 - std::cos(alpha))), 1e-6) << alpha;
  }
}

TEST(ParallelTransport, HolonomyOfAClosedCurveIsTheSolidAngleOfItsTangentIndicatrix) {
  // Non-planar closed polylines (edge tangents, Bergou's discrete setting): the transport
  // around the indicatrix polygon rotates u by its signed solid angle, computed here
  // independently by a fan of spherical triangles.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  int nonTrivial = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3> pts;
    const int n = 40;
    const Vec3 c1(unit(rng), unit(rng), unit(rng)), c2(unit(rng), unit(rng), unit(rng));
    for (int i = 0; i < n; ++i) {
      const double s = 2 * kPi * i / n;
      pts.push_back(Vec3(std::cos(s), std::sin(s), 0) + 0.6 * std::sin(2 * s) * c1 +
                    0.4 * std::cos(3 * s) * c2);
    }
    std::vector<Vec3> edges;
    for (int i = 0; i < n; ++i) edges.push_back((pts[(i + 1) % n] - pts[i]).normalized());
    BishopOptions o;
    o.distributeHolonomy = false;
    const BishopFrames f = bishopFrames(edges, true, o);
    const double omega = fanSolidAngle(edges);
    EXPECT_NEAR(wrap(f.holonomy - omega), 0, 1e-11) << "trial " << trial;
    if (std::abs(wrap(omega)) > 0.1) ++nonTrivial;
  }
  EXPECT_GT(nonTrivial, 10);  // the loops really are non-planar
}

TEST(ParallelTransport, DistributedHolonomyMakesTheFramePeriodicWithUniformTwist) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 9; ++i) {
    const double s = 2 * kPi * i / 9;
    pts.push_back({std::cos(s) + 0.3 * std::sin(2 * s), std::sin(s),
                   0.5 * std::sin(2 * s) + 0.4 * std::cos(3 * s)});
  }
  const CurveSamples c = Spline(pts, true).sample(0.03);
  BishopOptions o;
  o.arcLength = c.arcLength;
  const BishopFrames f = bishopFrames(c.tangents, true, o);
  ASSERT_GT(std::abs(f.holonomy), 0.1);
  const std::size_t n = f.frames.size();
  const double total = c.arcLength.back();
  for (std::size_t i = 0; i < n; ++i) {
    expectFrame(f.frames[i], c.tangents[i]);
    const std::size_t j = (i + 1) % n;
    // Twist of step i → j: angle from the transported u_i to u_j about t_j.
    const Vec3 moved = transportRotation(c.tangents[i], c.tangents[j]) * f.frames[i].col(1);
    const double step = c.arcLength[i + 1] - c.arcLength[i];
    EXPECT_NEAR(signedAngle(moved, f.frames[j].col(1), c.tangents[j]), -f.holonomy * step / total,
                1e-10)
        << "step " << i;
  }
}

TEST(ParallelTransport, RefusesBadTangents) {
  EXPECT_THROW(bishopFrames(std::vector<Vec3>{}, false), Error);
  EXPECT_THROW(bishopFrames(std::vector<Vec3>{Vec3::UnitX(), Vec3::Zero()}, false), Error);
  try {
    bishopFrames(std::vector<Vec3>{Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()}, false);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("between points 1 and 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tfd::core
