// Angle field of paper §6.3: Equation 5 (lifting held angles) and the jump-aware Laplacian of
// Equation 6 (core/edit/angle_field.h).
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <bit>
#include <cstdint>

#include <cmath>
#include <numbers>
#include <random>

#include "core/derived_cache.h"
#include "core/edit/angle_field.h"
#include "core/error.h"
#include "core/solve/harmonic_solver.h"
#include "core/structured_mesh.h"
#include "tests/support/random_vec3.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

std::shared_ptr<const TetMesh> jittered(int n, unsigned seed) {
  const auto box = makeBoxMesh(n, n, n, Vec3::Constant(-1), Vec3::Constant(1));
  std::vector<Vec3> p = box->positions();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!box->isBoundaryVertex(static_cast<int>(i))) p[i] += (2.0 / n) * test::drawVec3(u, rng);
  return std::make_shared<const TetMesh>(std::move(p), box->tets());
}

/// Tets whose centroid lies inside the ball; held = region vertices with a tet outside it.
struct Ball {
  std::vector<int> tets;
  RegionComplex region;
  std::vector<char> held;
  Ball(const TetMesh& mesh, const Vec3& c, double r, bool holdDomainSurface = false) {
    for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
      Vec3 m = Vec3::Zero();
      for (int v : mesh.tets()[t]) m += mesh.positions()[v] / 4;
      if ((m - c).norm() < r) tets.push_back(static_cast<int>(t));
    }
    region = regionComplex(mesh, tets);
    for (int v : region.vertices) {
      bool h = holdDomainSurface && mesh.isBoundaryVertex(v);
      for (int t : mesh.vertexTets(v)) h = h || region.localTet(t) < 0;
      held.push_back(h);
    }
  }
  int count(bool wantHeld) const {
    return static_cast<int>(std::count(held.begin(), held.end(), wantHeld ? 1 : 0));
  }
};

TEST(AngleField, ConstantBoundaryAngleAndZeroJumpsGiveAConstant) {
  const auto mesh = jittered(8, 1);
  for (const Vec3& centre : {Vec3(0.1, 0, -0.1), Vec3(0.7, 0.5, 0)}) {  // inside; at the surface
    const Ball ball(*mesh, centre, 0.8);
    ASSERT_GT(ball.count(false), 20);
    const int n = static_cast<int>(ball.region.vertices.size());
    std::vector<double> theta(n), jumps(ball.region.edges.size(), 0.0);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> noise(-3, 3);
    for (int i = 0; i < n; ++i) theta[i] = ball.held[i] ? 1.234 : noise(rng);
    const JumpSolveResult r = solveJumpLaplacian(*mesh, ball.region, ball.held, jumps, theta, 1);
    EXPECT_EQ(r.freeVertices, ball.count(false));
    for (int i = 0; i < n; ++i) EXPECT_NEAR(theta[i], 1.234, 1e-8) << "vertex " << i;
  }
}

TEST(AngleField, GradientJumpsShiftTheSolutionByTheirPotential) {
  // With g_ij = φ_j − φ_i and held θ = φ + c, Equation 6 is solved exactly by θ = φ + c (any
  // wrong sign or orientation of the jumps breaks this). φ is far from harmonic.
  const auto mesh = jittered(8, 4);
  const Ball ball(*mesh, Vec3(0.6, 0.1, 0.4), 0.9);  // reaches the domain surface: free there
  const auto phi = [&](int local) {
    const Vec3& p = mesh->positions()[ball.region.vertices[local]];
    return 3 * std::sin(2 * p.x()) * p.y() + p.z() * p.z() * 4;
  };
  const int n = static_cast<int>(ball.region.vertices.size());
  std::vector<double> theta(n), jumps(ball.region.edges.size());
  for (std::size_t e = 0; e < ball.region.edges.size(); ++e) {
    const auto& ends = mesh->edges()[ball.region.edges[e]];
    jumps[e] = phi(ball.region.localVertex(ends[1])) - phi(ball.region.localVertex(ends[0]));
  }
  for (int i = 0; i < n; ++i) theta[i] = ball.held[i] ? phi(i) + 0.5 : 0;
  solveJumpLaplacian(*mesh, ball.region, ball.held, jumps, theta, 1);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(theta[i], phi(i) + 0.5, 1e-7) << "vertex " << i;
}

TEST(AngleField, ZeroJumpColumnsAreTheHarmonicSolveOfEquation1) {
  const auto mesh = jittered(8, 6);
  const Ball ball(*mesh, Vec3(-0.2, 0.1, 0.3), 0.9);
  const int n = static_cast<int>(ball.region.vertices.size());
  std::vector<double> mine(2 * n), jumps(2 * ball.region.edges.size(), 0.0);
  std::vector<double> reference(2 * mesh->vertexCount());
  std::vector<int> free;
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {
    const Vec3& p = mesh->positions()[v];
    reference[2 * v] = std::exp(p.x()) * std::cos(p.y());
    reference[2 * v + 1] = p.z() * p.z() - p.x();
  }
  for (int i = 0; i < n; ++i) {
    const int v = ball.region.vertices[i];
    mine[2 * i] = reference[2 * v];
    mine[2 * i + 1] = reference[2 * v + 1];
    if (!ball.held[i]) free.push_back(v);
  }
  solveJumpLaplacian(*mesh, ball.region, ball.held, jumps, mine, 2, {1e-12, 5000});
  SolverOptions options;
  options.tolerance = 1e-12;
  HarmonicSolver::forRegion(mesh, free, options).solveColumns(reference, 2);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(mine[2 * i + c], reference[2 * ball.region.vertices[i] + c], 1e-9);
}

TEST(AngleField, LiftingRecoversAnAngleKnownModuloPiAlongHeldEdges) {
  const auto mesh = jittered(10, 8);
  const Ball ball(*mesh, Vec3::Zero(), 10);
  const int n = static_cast<int>(ball.region.vertices.size());
  // The true angle spans several π across the region; only its class modulo π is given.
  const auto truth = [&](int i) {
    const Vec3& p = mesh->positions()[ball.region.vertices[i]];
    return 1.5 * p.x() + p.y() * p.z();
  };
  std::vector<double> raw(n), jumps(ball.region.edges.size(), 0.0);
  for (int i = 0; i < n; ++i) raw[i] = std::remainder(truth(i), kPi);
  std::vector<char> all(n, 1);
  const std::vector<double> lifted = liftAngles(ball.region, all, raw, jumps, kPi);
  const double offset = lifted[0] - truth(0);
  EXPECT_NEAR(std::remainder(offset, kPi), 0, 1e-12);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(lifted[i] - truth(i), offset, 1e-12);
  // Jumps enter as θ_b ≈ θ_a + g_ab: constant raw angles with gradient jumps lift to the
  // potential.
  std::vector<double> constant(n, 0.0);
  for (std::size_t e = 0; e < ball.region.edges.size(); ++e) {
    const auto& ends = mesh->edges()[ball.region.edges[e]];
    jumps[e] = std::round(truth(ball.region.localVertex(ends[1]))) -
               std::round(truth(ball.region.localVertex(ends[0])));
    jumps[e] *= kPi;
  }
  const std::vector<double> steps = liftAngles(ball.region, all, constant, jumps, kPi);
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(steps[i] - steps[0], kPi * (std::round(truth(i)) - std::round(truth(0))), 1e-12);
}

TEST(AngleField, RefusesFreeVerticesWithoutAHeldNeighbourPiece) {
  const auto mesh = jittered(4, 9);
  const Ball ball(*mesh, Vec3::Zero(), 10);  // the whole mesh: nothing outside
  std::vector<char> none(ball.region.vertices.size(), 0);
  std::vector<double> theta(none.size(), 0.0), jumps(ball.region.edges.size(), 0.0);
  EXPECT_THROW(solveJumpLaplacian(*mesh, ball.region, none, jumps, theta, 1), Error);
}

TEST(AngleField, SameResultForOneAndTwoThreads) {
  const auto mesh = jittered(12, 10);
  const Ball ball(*mesh, Vec3(0.1, 0.2, 0), 0.8);
  const int n = static_cast<int>(ball.region.vertices.size());
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    derivedCache().clear();  // each run builds its own solver set-up
    std::vector<double> theta(n), jumps(ball.region.edges.size());
    for (int i = 0; i < n; ++i) theta[i] = ball.held[i] ? std::sin(i * 0.37) : 0;
    for (std::size_t e = 0; e < jumps.size(); ++e) jumps[e] = std::cos(e * 0.11) * 0.1;
    solveJumpLaplacian(*mesh, ball.region, ball.held, jumps, theta, 1);
    return theta;
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(AngleField, OneSystemSolvesEachRightHandSideLikeAFreshSolve) {
  const auto mesh = jittered(8, 11);
  const Ball ball(*mesh, Vec3(0.1, -0.1, 0.05), 0.7);
  const int n = static_cast<int>(ball.region.vertices.size());
  const JumpLaplacian system(*mesh, ball.region, ball.held);
  for (int width : {1, 3}) {
    std::vector<double> values(std::size_t(n) * width), jumps(ball.region.edges.size() * width);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::sin(0.3 * i + width);
    for (std::size_t e = 0; e < jumps.size(); ++e) jumps[e] = 0.05 * std::cos(0.7 * e * width);
    std::vector<double> once = values, fresh = values;
    const JumpSolveResult a = system.solve(jumps, once, width);
    const JumpSolveResult b =
        solveJumpLaplacian(*mesh, ball.region, ball.held, jumps, fresh, width);
    EXPECT_EQ(once, fresh) << width << " columns";
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_GT(a.iterations, 0);
    EXPECT_EQ(a.freeVertices, ball.count(false));
  }
  // Jumps of the first column alone: as if the other columns had zero jumps, bit for bit.
  std::vector<double> firstOnly(ball.region.edges.size()), padded(firstOnly.size() * 3, 0.0);
  for (std::size_t e = 0; e < firstOnly.size(); ++e)
    padded[3 * e] = firstOnly[e] = 0.05 * std::sin(0.9 * e);
  std::vector<double> threeColumns(std::size_t(n) * 3);
  for (std::size_t i = 0; i < threeColumns.size(); ++i) threeColumns[i] = std::cos(0.2 * i);
  std::vector<double> withPadding = threeColumns;
  system.solve(firstOnly, threeColumns, 3);
  system.solve(padded, withPadding, 3);
  for (std::size_t i = 0; i < withPadding.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint64_t>(threeColumns[i]),
              std::bit_cast<std::uint64_t>(withPadding[i]))
        << "entry " << i;
  std::vector<double> values(n), tooFewJumps(ball.region.edges.size() - 1);
  EXPECT_THROW(system.solve(tooFewJumps, values, 1), Error);
  EXPECT_THROW(system.solve(std::vector<double>(ball.region.edges.size()), values, 5), Error);
  std::vector<char> shortHeld(ball.held.begin(), ball.held.end() - 1);
  EXPECT_THROW(JumpLaplacian(*mesh, ball.region, shortHeld), Error);
}

}  // namespace
}  // namespace tfd::core
