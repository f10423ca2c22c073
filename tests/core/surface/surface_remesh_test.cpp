// Isotropic remeshing onto a known surface (core/surface/surface_remesh.h, Botsch & Kobbelt
// 2004): from a badly shaped start, every vertex ends on the projection surface, edge lengths
// gather around the target, the surface stays closed, manifold, outward and of the same genus,
// and the result is reproducible.
#include "core/surface/surface_remesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

std::vector<double> edgeLengths(const SurfaceMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::vector<double> out;
  for (const auto& [a, b] : edges) out.push_back((m.positions[a] - m.positions[b]).norm());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> referenced(const SurfaceMesh& m) {
  std::set<int> used;
  for (const auto& t : m.triangles) used.insert(t.begin(), t.end());
  return {used.begin(), used.end()};
}

/// The unit sphere's projection and a cube surface pushed onto it: corners crowd the start with
/// long thin triangles where the cube's faces meet.
Vec3 toSphere(const Vec3& p) { return p.normalized(); }

SurfaceMesh cubeOnSphere() {
  SurfaceMesh m = makeBox(Vec3(2, 2, 2), 0.5);
  for (Vec3& p : m.positions) p = toSphere(p);
  return m;
}

TEST(SurfaceRemesh, SphereEndsOnTheSurfaceWithEdgesNearTheTarget) {
  SurfaceMesh m = cubeOnSphere();
  const double target = 0.12;
  const auto before = edgeLengths(m);
  remeshIsotropic(m, target, toSphere);
  EXPECT_TRUE(closedSurfaceProblems(m).empty()) << closedSurfaceProblems(m)[0];
  EXPECT_EQ(eulerCharacteristic(m), 2);
  EXPECT_EQ(connectedComponents(m), 1);
  for (int v : referenced(m)) EXPECT_NEAR(m.positions[v].norm(), 1, 1e-12) << v;
  const auto lengths = edgeLengths(m);
  const double median = lengths[lengths.size() / 2];
  EXPECT_NEAR(median, target, 0.15 * target);
  // Splits and collapses bound the lengths to about [4/5, 4/3] L; smoothing moves a few out.
  const auto inBand = std::count_if(lengths.begin(), lengths.end(), [&](double l) {
    return l > 0.6 * target && l < 1.45 * target;
  });
  EXPECT_GT(double(inBand) / lengths.size(), 0.95);
  EXPECT_LT(lengths.back(), 2 * target);
  EXPECT_GT(before.back() / before.front(), 2) << "the start was not isotropic";
  // Outward, and the enclosed volume approaches the ball's (inscribed polyhedron: a bit less).
  const double ball = 4.0 / 3 * std::numbers::pi;
  EXPECT_GT(enclosedVolume(m), 0.97 * ball);
  EXPECT_LT(enclosedVolume(m), ball);
}

TEST(SurfaceRemesh, TorusKeepsItsGenusAndLiesOnTheTorus) {
  const double R = 1.0, a = 0.4;
  const auto project = [&](const Vec3& p) {
    const Vec3 ring = Vec3(p.x(), p.y(), 0).normalized() * R;
    return Vec3(ring + a * (p - ring).normalized());
  };
  // A coarse torus (about 0.35 edges) remeshed to a finer target.
  SurfaceMesh m = makeTorus(R, a, 0.35);
  const std::size_t trianglesBefore = m.triangles.size();
  remeshIsotropic(m, 0.08, project);
  EXPECT_TRUE(closedSurfaceProblems(m).empty());
  EXPECT_EQ(eulerCharacteristic(m), 0);
  EXPECT_GT(m.triangles.size(), 4 * trianglesBefore);
  for (int v : referenced(m)) {
    const Vec3& p = m.positions[v];
    EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), a, 1e-9) << v;
  }
  const auto lengths = edgeLengths(m);
  EXPECT_NEAR(lengths[lengths.size() / 2], 0.08, 0.15 * 0.08);
}

TEST(SurfaceRemesh, Deterministic) {
  SurfaceMesh a = cubeOnSphere(), b = cubeOnSphere();
  remeshIsotropic(a, 0.2, toSphere, 3);
  remeshIsotropic(b, 0.2, toSphere, 3);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.positions, b.positions);
}

}  // namespace
}  // namespace tfd::core
