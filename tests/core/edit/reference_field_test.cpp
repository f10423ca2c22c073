// Reference field U and jumps of paper §6.3 (core/edit/reference_field.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "core/design/parallel_transport.h"
#include "core/edit/reference_field.h"
#include "core/error.h"
#include "core/structured_mesh.h"
#include "tests/support/random_vec3.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

/// x wrapped to (−π, π].
double wrap(double x) { return x - 2 * kPi * std::ceil((x - kPi) / (2 * kPi)); }

TEST(ReferenceField, TriangleAreaIsTheHolonomyOfTransportAroundIt) {
  // The octant triangle covers an eighth of the sphere.
  EXPECT_NEAR(sphericalTriangleArea(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()), kPi / 2, 1e-15);
  EXPECT_NEAR(sphericalTriangleArea(Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitY()), -kPi / 2, 1e-15);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 a = randomUnit(rng), b = randomUnit(rng), c = randomUnit(rng);
    if (a.dot(b) < -0.9 || b.dot(c) < -0.9 || c.dot(a) < -0.9) continue;
    const Vec3 u = randomUnit(rng).cross(a).normalized();
    const Vec3 back =
        transportRotation(c, a) * transportRotation(b, c) * transportRotation(a, b) * u;
    EXPECT_NEAR(wrap(signedAngle(u, back, a) - sphericalTriangleArea(a, b, c)), 0, 1e-12);
  }
}

std::vector<int> allTets(const TetMesh& mesh) {
  std::vector<int> tets(mesh.tetCount());
  for (std::size_t t = 0; t < tets.size(); ++t) tets[t] = static_cast<int>(t);
  return tets;
}

/// A jittered box mesh (interior vertices moved, so that no order is special).
std::shared_ptr<const TetMesh> jittered(int n, unsigned seed) {
  const auto box = makeBoxMesh(n, n, n, Vec3::Constant(-1), Vec3::Constant(1));
  std::vector<Vec3> p = box->positions();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!box->isBoundaryVertex(static_cast<int>(i))) p[i] += (2.0 / n) * test::drawVec3(u, rng);
  return std::make_shared<const TetMesh>(std::move(p), box->tets());
}

/// A direction field that covers most of the sphere over the box: some jumps exceed π.
Vec3 sweep(const Vec3& p) {
  return (Eigen::AngleAxisd(3.25 * p.x(), Vec3::UnitY()) *
          Eigen::AngleAxisd(2.75 * p.y(), Vec3::UnitX()) * Vec3(0.2 * p.z(), 0, 1).normalized());
}

struct Fixture {
  std::shared_ptr<const TetMesh> mesh;
  RegionComplex region;
  std::vector<Vec3> n;
  ReferenceField ref;
  Fixture(std::shared_ptr<const TetMesh> m, const std::vector<int>& tets) : mesh(std::move(m)) {
    region = regionComplex(*mesh, tets);
    for (int v : region.vertices) n.push_back(sweep(mesh->positions()[v]));
    ref = referenceField(*mesh, region, n, static_cast<int>(region.vertices.size() / 2),
                         Vec3::UnitX());
  }
  double g(int a, int b) const { return orientedJump(ref.jumps[regionEdge(region, a, b)], a, b); }
};

TEST(ReferenceField, UIsATransportedUnitNormalAndJumpsMatchTransportPerEdge) {
  const Fixture f(jittered(7, 3), allTets(*jittered(7, 3)));
  EXPECT_EQ(f.ref.nonBallSteps, 0);
  const int n = static_cast<int>(f.region.vertices.size());
  int zero = 0;
  double largest = 0;
  for (int a = 0; a < n; ++a) {
    EXPECT_NEAR(f.ref.reference[a].norm(), 1, 1e-14);
    EXPECT_NEAR(f.ref.reference[a].dot(f.n[a]), 0, 1e-14);
    for (int k = f.region.start[a]; k < f.region.start[a + 1]; ++k) {
      const int b = f.region.neighbour[k];
      // U_b rotated by g_ab about N_b is the transport of U_a (modulo 2π).
      const Vec3 moved = transportRotation(f.n[a], f.n[b]) * f.ref.reference[a];
      EXPECT_NEAR(wrap(signedAngle(f.ref.reference[b], moved, f.n[b]) - f.g(a, b)), 0, 1e-11);
      EXPECT_EQ(f.g(a, b), -f.g(b, a));
      zero += f.g(a, b) == 0;
      largest = std::max(largest, std::abs(f.g(a, b)));
    }
  }
  EXPECT_GE(zero, 2 * (n - 1)) << "the propagation tree's edges have jump zero";
  // Beyond π: an angle measured per edge (wrapped to (−π, π]) would be off by 2π there.
  EXPECT_GT(largest, kPi) << "the test field should make large jumps";
}

TEST(ReferenceField, JumpsSumToTheHolonomyAroundEveryTriangleAndEveryInteriorEdge) {
  for (unsigned seed : {1u, 2u}) {
    const auto mesh = jittered(6, seed);
    const Fixture f(mesh, allTets(*mesh));
    EXPECT_EQ(f.ref.nonBallSteps, 0);
    EXPECT_LT(f.ref.maxHolonomyDefect, 1e-12);
    // Every triangle of the region (no 2πk allowed).
    for (int t : f.region.tets) {
      const auto& tet = mesh->tets()[t];
      for (int skip = 0; skip < 4; ++skip) {
        int c[3], k = 0;
        for (int i = 0; i < 4; ++i)
          if (i != skip) c[k++] = f.region.localVertex(tet[i]);
        const double sum = f.g(c[0], c[1]) + f.g(c[1], c[2]) + f.g(c[2], c[0]);
        EXPECT_NEAR(sum, sphericalTriangleArea(f.n[c[0]], f.n[c[1]], f.n[c[2]]), 1e-12);
      }
    }
    // The loop of vertices around each interior edge (its link, through the tets around it):
    // the jumps along it sum to the area of the spherical polygon, fanned from its first vertex.
    int loops = 0;
    for (std::size_t e = 0; e < mesh->edges().size(); ++e) {
      const auto [p, q] = mesh->edges()[e];
      if (mesh->isBoundaryVertex(p) && mesh->isBoundaryVertex(q)) continue;
      std::map<int, std::vector<int>> link;  // link vertex -> its link neighbours
      for (int t : mesh->vertexTets(p)) {
        const auto& tet = mesh->tets()[t];
        if (std::find(tet.begin(), tet.end(), q) == tet.end()) continue;
        int o[2], k = 0;
        for (int v : tet)
          if (v != p && v != q) o[k++] = v;
        link[o[0]].push_back(o[1]);
        link[o[1]].push_back(o[0]);
      }
      std::vector<int> cycle{link.begin()->first};
      for (int prev = -1;;) {
        const auto& next = link[cycle.back()];
        const int go = next[0] != prev ? next[0] : next[1];
        if (go == cycle.front()) break;
        prev = cycle.back();
        cycle.push_back(go);
      }
      ASSERT_EQ(cycle.size(), link.size());
      double jumps = 0, area = 0;
      for (std::size_t i = 0; i < cycle.size(); ++i) {
        const int a = f.region.localVertex(cycle[i]);
        const int b = f.region.localVertex(cycle[(i + 1) % cycle.size()]);
        jumps += f.g(a, b);
        if (i > 0 && i + 1 < cycle.size())
          area += sphericalTriangleArea(f.n[f.region.localVertex(cycle[0])], f.n[a], f.n[b]);
      }
      EXPECT_NEAR(jumps, area, 1e-11) << "edge " << e;
      ++loops;
    }
    EXPECT_GT(loops, 500);
  }
}

TEST(ReferenceField, BallShapedSubRegionsNeedNoNonBallStep) {
  const auto mesh = jittered(9, 5);
  std::vector<int> ball;
  for (std::size_t t = 0; t < mesh->tetCount(); ++t) {
    Vec3 c = Vec3::Zero();
    for (int v : mesh->tets()[t]) c += mesh->positions()[v] / 4;
    if ((c - Vec3(0.3, -0.2, 0.1)).norm() < 0.6) ball.push_back(static_cast<int>(t));
  }
  const Fixture f(mesh, ball);
  EXPECT_EQ(f.ref.nonBallSteps, 0);
  EXPECT_LT(f.ref.maxHolonomyDefect, 1e-12);
}

TEST(ReferenceField, RefusesRegionsNotConnectedThroughFaces) {
  const auto mesh = makeBoxMesh(2, 2, 2, Vec3::Zero(), Vec3(2, 2, 2));
  // Tet 0 and a tet that shares exactly one edge with it: connected, but not through a face.
  int partner = -1;
  for (std::size_t t = 1; t < mesh->tetCount() && partner < 0; ++t) {
    int common = 0;
    for (int v : mesh->tets()[t])
      common += std::count(mesh->tets()[0].begin(), mesh->tets()[0].end(), v);
    if (common == 2) partner = static_cast<int>(t);
  }
  ASSERT_GE(partner, 0);
  const RegionComplex region = regionComplex(*mesh, {0, partner});
  ASSERT_EQ(region.components(), 1);
  const std::vector<Vec3> n(region.vertices.size(), Vec3::UnitZ());
  EXPECT_THROW(referenceField(*mesh, region, n, 0, Vec3::UnitX()), Error);
}

}  // namespace
}  // namespace tfd::core
