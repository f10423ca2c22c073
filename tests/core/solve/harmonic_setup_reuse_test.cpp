// Reuse of a harmonic solver's set-up (multigrid hierarchy, blocks, order) kept for the mesh
// (SolverOptions::reuseSetup, core::derivedCache()): a reused set-up gives bitwise the solution
// of a fresh one, for 1 and 2 threads; a changed matrix, free set or option never reuses one;
// region solves and propagation re-cooks reuse theirs.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/derived_cache.h"
#include "core/design/propagate.h"
#include "core/linalg/amg.h"
#include "core/solve/harmonic_solver.h"
#include "core/solve/laplacian.h"
#include "tests/core/solve/solver_test_meshes.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

using testing::hashUnit;
using testing::jitteredBox;

struct Problem {
  std::vector<unsigned char> fixed;
  std::vector<Tensor> values;
};

/// Every 53rd vertex fixed to a pseudo-random traceless tensor (seeded by `seed`).
Problem problem(const TetMesh& mesh, int seed, int stride = 53) {
  Problem p{std::vector<unsigned char>(mesh.vertexCount(), 0),
            std::vector<Tensor>(mesh.vertexCount())};
  for (int v = 0; v < static_cast<int>(mesh.vertexCount()); v += stride) {
    p.fixed[v] = 1;
    p.values[v] = Tensor::fromVec5(
        {hashUnit(v + seed), hashUnit(v + 7 * seed), 0.25, hashUnit(v + 3 * seed), -0.5});
  }
  return p;
}

SolverOptions fresh() {
  SolverOptions o;
  o.reuseSetup = false;
  return o;
}

void expectBitwiseEqual(const SolveResult& a, const SolveResult& b) {
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.relativeResidual, b.relativeResidual);
  ASSERT_EQ(a.values.size(), b.values.size());
  for (std::size_t v = 0; v < a.values.size(); ++v) ASSERT_EQ(a.values[v], b.values[v]) << v;
}

TEST(HarmonicSetupReuse, SameSystemReusesAndGivesTheFreshSolutionBitwise) {
  const auto mesh = jitteredBox(10);
  const Problem first = problem(*mesh, 1), second = problem(*mesh, 2);  // same fixed set
  derivedCache().clear();
  const HarmonicSolver a(mesh, first.fixed);
  EXPECT_FALSE(a.setupReused());
  EXPECT_EQ(derivedCache().size(), 1u);
  a.solve(first.values);
  const HarmonicSolver b(mesh, second.fixed);  // a re-cook: new values, same matrix
  EXPECT_TRUE(b.setupReused());
  EXPECT_EQ(&b.preconditioner(), &a.preconditioner());
  const HarmonicSolver c(mesh, second.fixed, fresh());
  EXPECT_FALSE(c.setupReused());
  expectBitwiseEqual(b.solve(second.values), c.solve(second.values));
}

TEST(HarmonicSetupReuse, GivenStiffnessRowsAreComparedEntryByEntry) {
  const auto mesh = jitteredBox(9);
  const Problem p = problem(*mesh, 3);
  const StiffnessRows rows = assembleStiffness(*mesh);
  const HarmonicSolver a(mesh, p.fixed, rows);
  EXPECT_FALSE(a.setupReused());
  const StiffnessRows copy = assembleStiffness(*mesh);  // equal rows, another object
  EXPECT_TRUE(HarmonicSolver(mesh, p.fixed, copy).setupReused());

  // Another matrix on the same mesh and fixed set: the stiffness of the same tets with the
  // vertices moved. Reusing the kept set-up would solve the old system.
  std::vector<Vec3> moved = mesh->positions();
  for (std::size_t v = 0; v < moved.size(); ++v) moved[v] *= 1.0 + 0.3 * (moved[v].x() + 1.5);
  const StiffnessRows other = assembleStiffness(TetMesh(moved, mesh->tets()));
  const HarmonicSolver b(mesh, p.fixed, other);
  EXPECT_FALSE(b.setupReused());
  const SolveResult reusedOrNot = b.solve(p.values);
  expectBitwiseEqual(reusedOrNot, HarmonicSolver(mesh, p.fixed, other, fresh()).solve(p.values));
  // ... and the two systems have different solutions (so a stale reuse would show).
  const SolveResult old = a.solve(p.values);
  double difference = 0;
  for (std::size_t v = 0; v < old.values.size(); ++v)
    difference = std::max(difference, testing::maxDifference(old.values[v], reusedOrNot.values[v]));
  EXPECT_GT(difference, 1e-3);

  // One changed entry (kept symmetric) is enough.
  StiffnessRows nudged = assembleStiffness(*mesh);
  int row = 0;
  while (p.fixed[row]) ++row;
  for (int m = nudged.matrix.start[row]; m < nudged.matrix.start[row + 1]; ++m)
    if (nudged.matrix.index[m] == row) nudged.matrix.value[m] *= 1.0 + 1e-15;
  EXPECT_FALSE(HarmonicSolver(mesh, p.fixed, nudged).setupReused());
}

TEST(HarmonicSetupReuse, OtherFixedSetOrOptionsAreNotReused) {
  const auto mesh = jitteredBox(8);
  const Problem p = problem(*mesh, 4), q = problem(*mesh, 4, 41);
  const HarmonicSolver a(mesh, p.fixed);
  EXPECT_FALSE(HarmonicSolver(mesh, q.fixed).setupReused());
  SolverOptions doublePrecision;
  doublePrecision.singlePrecisionPreconditioner = false;
  EXPECT_FALSE(HarmonicSolver(mesh, p.fixed, doublePrecision).setupReused());
  SolverOptions bound;
  bound.lambdaMaxBound = a.preconditioner().levels()[0].lambdaMax;
  EXPECT_FALSE(HarmonicSolver(mesh, p.fixed, bound).setupReused());
  // Rows the solver assembles itself are not taken for given rows' set-ups and vice versa
  // (they are only known equal when compared).
  const StiffnessRows rows = assembleStiffness(*mesh);
  const Problem r = problem(*mesh, 5, 29);
  const HarmonicSolver given(mesh, r.fixed, rows);
  EXPECT_FALSE(HarmonicSolver(mesh, r.fixed).setupReused());
  // Tolerance and iteration limit are not part of the set-up.
  SolverOptions loose;
  loose.tolerance = 1e-4;
  loose.maxIterations = 50;
  EXPECT_TRUE(HarmonicSolver(mesh, p.fixed, loose).setupReused());
  // Another mesh object with the same vertices and tets has its own entries.
  const auto copy = std::make_shared<const TetMesh>(mesh->positions(), mesh->tets());
  EXPECT_FALSE(HarmonicSolver(copy, p.fixed).setupReused());
}

TEST(HarmonicSetupReuse, EntriesGoWithTheirMesh) {
  derivedCache().clear();
  auto mesh = jitteredBox(6);
  const Problem p = problem(*mesh, 10);
  HarmonicSolver(mesh, p.fixed).solve(p.values);
  EXPECT_EQ(derivedCache().size(), 1u);
  std::weak_ptr<const TetMesh> gone = mesh;
  mesh.reset();
  EXPECT_TRUE(gone.expired());  // the cache does not keep the mesh alive
  // A new mesh (possibly at the same address) never sees the dead mesh's entry.
  const auto other = jitteredBox(6);
  EXPECT_FALSE(HarmonicSolver(other, p.fixed).setupReused());
  EXPECT_EQ(derivedCache().size(), 1u);  // the dead mesh's entry was dropped
}

TEST(HarmonicSetupReuse, BudgetAndEntryLimitEvict) {
  const auto mesh = jitteredBox(6);
  const Problem p = problem(*mesh, 6);
  derivedCache().setBudget(0);
  EXPECT_FALSE(HarmonicSolver(mesh, p.fixed).setupReused());
  EXPECT_FALSE(HarmonicSolver(mesh, p.fixed).setupReused());
  EXPECT_EQ(derivedCache().size(), 0u);
  derivedCache().setBudget(std::size_t(1) << 30);
  std::vector<int> region;
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); ++v)
    if (!mesh->isBoundaryVertex(v)) region.push_back(v);
  for (std::size_t k = 0; k <= DerivedCache::kMaxEntries; ++k) {
    std::vector<int> free(region.begin(), region.end() - static_cast<long>(k));
    EXPECT_FALSE(HarmonicSolver::forRegion(mesh, free).setupReused()) << k;
  }
  EXPECT_EQ(derivedCache().size(), DerivedCache::kMaxEntries);
  // The first region was used least recently: evicted; the last one is kept.
  EXPECT_FALSE(HarmonicSolver::forRegion(mesh, region).setupReused());
  std::vector<int> last(region.begin(), region.end() - DerivedCache::kMaxEntries);
  EXPECT_TRUE(HarmonicSolver::forRegion(mesh, last).setupReused());
}

TEST(HarmonicSetupReuse, RegionSolvesReuseTheirSetUp) {
  const auto mesh = jitteredBox(10);
  std::vector<int> free;
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); ++v)
    if (mesh->positions()[v].norm() < 0.6) free.push_back(v);
  const Problem p = problem(*mesh, 7, 1);  // every vertex has a value
  const HarmonicSolver a = HarmonicSolver::forRegion(mesh, free);
  const HarmonicSolver b = HarmonicSolver::forRegion(mesh, free);
  EXPECT_FALSE(a.setupReused());
  EXPECT_TRUE(b.setupReused());
  expectBitwiseEqual(b.solve(p.values),
                     HarmonicSolver::forRegion(mesh, free, fresh()).solve(p.values));
}

TEST(HarmonicSetupReuse, SetUpBuiltOnOneThreadReusedOnTwoIsBitwiseFresh) {
  const auto mesh = test::mappedTorus(48, 7);
  const Problem first = problem(*mesh, 8, 211), second = problem(*mesh, 9, 211);
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    HarmonicSolver(mesh, first.fixed).solve(first.values);
  }
  tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
  const HarmonicSolver reused(mesh, second.fixed);
  ASSERT_TRUE(reused.setupReused());
  expectBitwiseEqual(reused.solve(second.values),
                     HarmonicSolver(mesh, second.fixed, fresh()).solve(second.values));
}

TEST(HarmonicSetupReuse, PropagationReCookReusesBothSetUps) {
  const auto mesh = test::carvedSolid(
      16, Vec3(-1, -1, -1), Vec3(1, 1, 1), [](const Vec3& p) { return p.norm() < 0.95; }, 0.1);
  ConstraintSet set;
  PointElement p;
  p.field = makeTensorLinearization(Vec3(0.2, 0.1, 0), Mat3::Identity(), Vec3(1, 0.2, -0.8));
  set.points = {p};
  const PropagateResult first = propagate(mesh, set);
  EXPECT_EQ(first.report.reusedSetups, 0);
  set.points[0].field =
      makeTensorLinearization(Vec3(0.2, 0.1, 0), Mat3::Identity(), Vec3(0.7, 0.4, -0.9));
  const PropagateResult again = propagate(mesh, set);
  EXPECT_EQ(again.report.reusedSetups, 2);
  EXPECT_NE(again.report.summary().find("2 solver set-up(s) reused"), std::string::npos);
  const auto copy = std::make_shared<const TetMesh>(mesh->positions(), mesh->tets());
  const PropagateResult fresh = propagate(copy, set);
  EXPECT_EQ(fresh.report.reusedSetups, 0);
  EXPECT_EQ(again.report.firstIterations, fresh.report.firstIterations);
  EXPECT_EQ(again.report.secondIterations, fresh.report.secondIterations);
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v)
    ASSERT_EQ(again.field.values()[v], fresh.field.values()[v]) << v;
  EXPECT_NE(again.field.values(), first.field.values());
}

}  // namespace
}  // namespace tfd::core
