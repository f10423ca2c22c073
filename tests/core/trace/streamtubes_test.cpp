// Bishop frames and streamtubes (core/trace/bishop_frames.h, streamtubes.h): frames that do
// not rotate about the tangent (checked against discrete parallel transport, algorithms note
// §10, and against the helix's known torsion), and tubes that are closed, outward-oriented
// surfaces enclosing the volume of their profile times their length.
#include "core/trace/streamtubes.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/error.h"
#include "core/trace/bishop_frames.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

/// A helix of radius a and pitch 2πc, n points over `turns` turns.
std::vector<Vec3> helix(double a, double c, double turns, int n) {
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * turns * i / (n - 1);
    p.emplace_back(a * std::cos(t), a * std::sin(t), c * t);
  }
  return p;
}

/// Discrete parallel transport (Bergou et al. 2008): the rotation about t0 × t1 taking t0 to t1.
Vec3 transport(const Vec3& t0, const Vec3& t1, const Vec3& x) {
  const Vec3 axis = t0.cross(t1);
  const double s = axis.norm(), c = t0.dot(t1);
  if (s < 1e-300) return x;
  const Vec3 k = axis / s;
  return x * c + k.cross(x) * s + k * k.dot(x) * (1 - c);
}

/// Signed angle from a to b about axis t (a, b ⊥ t).
double angleAbout(const Vec3& t, const Vec3& a, const Vec3& b) {
  return std::atan2(t.dot(a.cross(b)), a.dot(b));
}

TEST(BishopFrames, OrthonormalAndTwistFreeAlongAHelix) {
  const double a = 1, c = 0.3;
  const auto points = helix(a, c, 2, 401);
  const auto frames = bishopFrames(points);
  ASSERT_EQ(frames.size(), points.size());
  double worstTwist = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    EXPECT_NEAR(f.tangent.norm(), 1, 1e-12);
    EXPECT_NEAR(f.normal.norm(), 1, 1e-12);
    EXPECT_NEAR(f.tangent.dot(f.normal), 0, 1e-12);
    EXPECT_NEAR((f.tangent.cross(f.normal) - f.binormal).norm(), 0, 1e-12);
    if (i == 0) continue;
    // Rotation about the tangent between consecutive frames, beyond the minimal rotation.
    const Vec3 moved = transport(frames[i - 1].tangent, f.tangent, frames[i - 1].normal);
    worstTwist = std::max(worstTwist, std::abs(angleAbout(f.tangent, moved, f.normal)));
  }
  // The frame itself turns about the tangent by τ·Δs ≈ 0.018 rad per step against the
  // Frenet frame; beyond the minimal rotation it turns by less than 1e-5 rad.
  EXPECT_LT(worstTwist, 1e-5);
  // Against the Frenet frame, a rotation-minimising frame turns by −τ·s (torsion τ = c/(a²+c²)):
  // the total over the helix, from the analytic Frenet normal −(cos t, sin t, 0).
  const auto frenet = [&](std::size_t i) {
    const double t = 2 * kPi * 2 * double(i) / (points.size() - 1);
    return Vec3(-std::cos(t), -std::sin(t), 0);
  };
  const double arc = 2 * 2 * kPi * std::hypot(a, c), torsion = c / (a * a + c * c);
  double accumulated = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const double before = angleAbout(frames[i - 1].tangent, frenet(i - 1), frames[i - 1].normal);
    const double after = angleAbout(frames[i].tangent, frenet(i), frames[i].normal);
    accumulated += std::remainder(after - before, 2 * kPi);
  }
  EXPECT_NEAR(accumulated, -torsion * arc, 2e-3 * torsion * arc);
}

TEST(BishopFrames, APlanarCurveKeepsItsPlaneNormal) {
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) {
    const double t = 0.05 * i;
    points.emplace_back(t, std::sin(3 * t), 0);
  }
  // Whichever the first normal is, the plane's normal z stays a frame axis: no twist.
  const auto frames = bishopFrames(points);
  for (const Frame& f : frames)
    EXPECT_NEAR(std::max(std::abs(f.normal.z()), std::abs(f.binormal.z())), 1, 1e-12);
}

struct EdgeCheck {
  bool closed = true;
  double volume = 0;
};

/// Every directed edge of the triangles [t0, t1) appears once and its reverse once (closed,
/// consistently oriented); the volume by the divergence theorem.
EdgeCheck checkClosed(const SurfaceMesh& m, std::size_t t0, std::size_t t1) {
  std::map<std::pair<int, int>, int> directed;
  EdgeCheck out;
  for (std::size_t t = t0; t < t1; ++t) {
    const auto& tri = m.triangles[t];
    for (int k = 0; k < 3; ++k) ++directed[{tri[k], tri[(k + 1) % 3]}];
    out.volume += m.positions[tri[0]].dot(m.positions[tri[1]].cross(m.positions[tri[2]])) / 6;
  }
  for (const auto& [edge, count] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (count != 1 || back == directed.end() || back->second != 1) out.closed = false;
  }
  return out;
}

Polylines sampleLines() {
  Polylines lines;
  Polyline straight;
  for (int i = 0; i <= 10; ++i) straight.points.emplace_back(0.1 * i, 2, 0);
  straight.eigenvalues.assign(straight.points.size(), Vec3(1, 0, -1));
  Polyline coil;
  coil.points = helix(0.5, 0.1, 1.5, 300);
  for (std::size_t i = 0; i < coil.points.size(); ++i)
    coil.eigenvalues.emplace_back(1 + double(i) / 299, 0, -1);
  Polyline single;
  single.points = {Vec3(5, 5, 5)};
  single.eigenvalues = {Vec3::Zero()};
  lines.lines = {straight, single, coil};
  return lines;
}

TEST(Streamtubes, EachLineIsAClosedOutwardTubeWithTheProfilesVolume) {
  const Polylines lines = sampleLines();
  for (TubeProfile profile : {TubeProfile::Circle, TubeProfile::Ribbon}) {
    TubeOptions o;
    o.profile = profile;
    o.radius = 0.02;
    o.sides = 12;
    const SurfaceMesh mesh = sweepTubes(lines, o);
    // The one-point line is skipped: tubes of 11·m + 2 and 300·m + 2 vertices.
    const std::size_t m = profile == TubeProfile::Circle ? 12 : 4;
    ASSERT_EQ(mesh.positions.size(), 11 * m + 2 + 300 * m + 2);
    ASSERT_EQ(mesh.triangles.size(), 2 * m * 11 + 2 * m * 300);
    const double area = profile == TubeProfile::Circle
                            ? 0.5 * 12 * std::sin(2 * kPi / 12) * o.radius * o.radius
                            : 4 * o.radius * o.radius * o.ribbonThickness;
    const EdgeCheck straight = checkClosed(mesh, 0, 2 * m * 11);
    EXPECT_TRUE(straight.closed);
    EXPECT_NEAR(straight.volume, area * 1.0, 1e-12);
    const EdgeCheck coil = checkClosed(mesh, 2 * m * 11, mesh.triangles.size());
    EXPECT_TRUE(coil.closed);
    EXPECT_NEAR(coil.volume, area * lines.lines[2].length(), 1e-3 * area * lines.lines[2].length());
    // Every ring vertex sits at the profile's distance from its line point.
    const double far =
        profile == TubeProfile::Circle ? o.radius : o.radius * std::hypot(1.0, o.ribbonThickness);
    for (std::size_t i = 0; i < 11; ++i)
      for (std::size_t j = 0; j < m; ++j)
        EXPECT_NEAR((mesh.positions[i * m + j] - lines.lines[0].points[i]).norm(), far, 1e-12);
  }
}

TEST(Streamtubes, WidthFollowsTheChosenEigenvalue) {
  const Polylines lines = sampleLines();
  TubeOptions o;
  o.radius = 0.05;
  o.width = TubeWidth::Major;
  o.minWidth = 0.2;
  const SurfaceMesh mesh = sweepTubes(lines, o);
  const std::size_t m = 8, coil0 = 11 * m + 2;
  // |λ1| runs from 1 (the straight line and the coil's start) to 2 (the coil's end).
  EXPECT_NEAR((mesh.positions[0] - lines.lines[0].points[0]).norm(), 0.2 * 0.05, 1e-12);
  EXPECT_NEAR((mesh.positions[coil0 + 299 * m] - lines.lines[2].points[299]).norm(), 0.05, 1e-12);
  EXPECT_NEAR((mesh.positions[coil0 + 150 * m] - lines.lines[2].points[150]).norm(),
              0.05 * (0.2 + 0.8 * 150.0 / 299), 1e-12);
}

TEST(Streamtubes, OneAndTwoThreadsGiveTheSameMeshAndBadOptionsAreRefused) {
  Polylines lines = sampleLines();
  for (int k = 0; k < 50; ++k) lines.lines.push_back(lines.lines[2]);
  const auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    return sweepTubes(lines, {});
  };
  const SurfaceMesh a = run(1), b = run(2);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  TubeOptions bad;
  bad.sides = 2;
  EXPECT_THROW(sweepTubes(lines, bad), Error);
  bad = {};
  bad.radius = 0;
  EXPECT_THROW(sweepTubes(lines, bad), Error);
}

}  // namespace
}  // namespace tfd::core
