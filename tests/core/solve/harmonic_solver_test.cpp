// Harmonic solver (core/solve/harmonic_solver.h): linear reproduction, agreement with a direct
// solve, region solves, warm start, determinism, errors and cancellation.
#include "core/solve/harmonic_solver.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <Eigen/SparseCholesky>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "core/linalg/amg.h"
#include "core/solve/laplacian.h"
#include "tests/core/solve/solver_test_meshes.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

using testing::hashUnit;
using testing::jitteredBox;
using testing::linearTensor;
using testing::maxDifference;

std::vector<unsigned char> boundaryMask(const TetMesh& mesh) {
  std::vector<unsigned char> fixed(mesh.vertexCount(), 0);
  for (int v : mesh.boundaryVertices()) fixed[v] = 1;
  return fixed;
}

/// Boundary fixed to a linear field, interior free (started from zero): the solve must
/// reproduce the linear field (P1 contains it and it is discretely harmonic).
double linearReproductionError(std::shared_ptr<const TetMesh> mesh) {
  std::vector<Tensor> values(mesh->vertexCount());
  for (int v : mesh->boundaryVertices()) values[v] = linearTensor(mesh->positions()[v]);
  SolverOptions options;
  options.tolerance = 1e-12;
  const HarmonicSolver solver(mesh, boundaryMask(*mesh), options);
  const SolveResult result = solver.solve(values);
  double error = 0;
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v)
    error = std::max(error, maxDifference(result.values[v], linearTensor(mesh->positions()[v])));
  return error;
}

TEST(HarmonicSolver, ReproducesLinearFieldsOnBoxMeshes) {
  EXPECT_LT(linearReproductionError(makeBoxMesh(9, 7, 8, Vec3(-1, -2, 0), Vec3(2, 1, 1.5))), 1e-8);
  EXPECT_LT(linearReproductionError(jitteredBox(10)), 1e-8);
}

TEST(HarmonicSolver, ReproducesLinearFieldsOnMeshesOfEachSolid) {
  // Ball and torus with curved boundaries, a carved (jittered, non-convex, genus-2) double torus.
  EXPECT_LT(linearReproductionError(test::mappedBall(10)), 1e-8) << "ball";
  EXPECT_LT(linearReproductionError(test::mappedTorus(24, 4)), 1e-8) << "torus";
  const auto doubleTorus = test::carvedSolid(
      24, Vec3(-3, -1.5, -0.5), Vec3(3, 1.5, 0.5),
      [](const Vec3& p) { return test::insideDoubleTorus(p); }, 0.15);
  EXPECT_LT(linearReproductionError(doubleTorus), 1e-8) << "double torus";
}

TEST(HarmonicSolver, AgreesWithADirectSparseCholeskySolve) {
  const auto mesh = jitteredBox(8);
  const StiffnessRows k = assembleStiffness(*mesh);
  // Fix a few scattered vertices only (the badly conditioned "first solve" situation).
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  std::vector<Tensor> values(mesh->vertexCount());
  for (int v : {5, 77, 301, 512}) {
    fixed[v] = 1;
    values[v] = Tensor::fromVec5(
        {hashUnit(v), hashUnit(v + 1), hashUnit(v + 2), hashUnit(v + 3), hashUnit(v + 4)});
  }
  const HarmonicSolver solver(mesh, fixed);
  const SolveResult result = solver.solve(values);
  EXPECT_LE(result.relativeResidual, 1e-8);
  // Reference: Eigen's simplicial LDLᵀ on the free block, per component.
  std::vector<int> freeIndex(mesh->vertexCount(), -1);
  std::vector<int> free;
  for (std::size_t v = 0; v < fixed.size(); ++v)
    if (!fixed[v]) {
      freeIndex[v] = static_cast<int>(free.size());
      free.push_back(static_cast<int>(v));
    }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < k.matrix.rows; ++i)
    for (int m = k.matrix.start[i]; m < k.matrix.start[i + 1]; ++m)
      if (freeIndex[i] >= 0 && freeIndex[k.matrix.index[m]] >= 0)
        triplets.emplace_back(freeIndex[i], freeIndex[k.matrix.index[m]], k.matrix.value[m]);
  Eigen::SparseMatrix<double> a(free.size(), free.size());
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  double worst = 0, scale = 0;
  for (int c = 0; c < 5; ++c) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(free.size());
    for (int i = 0; i < k.matrix.rows; ++i) {
      if (freeIndex[i] < 0) continue;
      for (int m = k.matrix.start[i]; m < k.matrix.start[i + 1]; ++m)
        if (fixed[k.matrix.index[m]])
          b[freeIndex[i]] -= k.matrix.value[m] * values[k.matrix.index[m]].vec5()[c];
    }
    const Eigen::VectorXd x = ldlt.solve(b);
    for (std::size_t i = 0; i < free.size(); ++i) {
      worst = std::max(worst, std::abs(x[i] - result.values[free[i]].vec5()[c]));
      scale = std::max(scale, std::abs(x[i]));
    }
  }
  EXPECT_LT(worst, 1e-6 * scale);
  // Fixed values come back bitwise.
  for (int v : {5, 77, 301, 512}) EXPECT_EQ(result.values[v], values[v]);
}

TEST(HarmonicSolver, RegionSolveKeepsOutsideBitwiseAndIsHarmonicInside) {
  const auto mesh = jitteredBox(12);
  std::vector<Tensor> values(mesh->vertexCount());
  for (std::size_t v = 0; v < values.size(); ++v) {
    const Vec3& p = mesh->positions()[v];
    values[v] = Tensor{std::sin(3 * p.x()), std::cos(2 * p.y()) * p.z(), 0,
                       p.x() * p.y(),       std::sin(p.z() + p.x()),     0.3}
                    .deviator();
  }
  std::vector<int> region;
  for (std::size_t v = 0; v < values.size(); ++v)
    if ((mesh->positions()[v] - Vec3(0.2, -0.1, 0.1)).norm() < 0.45)
      region.push_back(static_cast<int>(v));
  ASSERT_GT(region.size(), 50u);
  const HarmonicSolver solver = HarmonicSolver::forRegion(mesh, region);
  EXPECT_EQ(solver.freeCount(), region.size());
  const SolveResult result = solver.solve(values);
  std::vector<unsigned char> inRegion(values.size(), 0);
  for (int v : region) inRegion[v] = 1;
  for (std::size_t v = 0; v < values.size(); ++v)
    if (!inRegion[v]) {
      ASSERT_EQ(result.values[v], values[v]) << "vertex " << v << " changed";
    }
  // Discrete Laplacian ≈ 0 at the free rows, relative to the size of the boundary coupling.
  const StiffnessRows rows = assembleStiffnessRows(*mesh, region);
  for (int c = 0; c < 5; ++c) {
    std::vector<double> u(values.size()), outside(values.size(), 0.0);
    for (std::size_t v = 0; v < values.size(); ++v) {
      u[v] = result.values[v].vec5()[c];
      if (!inRegion[v]) outside[v] = u[v];
    }
    const auto ku = applyStiffness(rows, u);
    const auto kb = applyStiffness(rows, outside);
    double defect = 0, reference = 0;
    for (std::size_t i = 0; i < ku.size(); ++i) {
      defect += ku[i] * ku[i];
      reference += kb[i] * kb[i];
    }
    EXPECT_LT(std::sqrt(defect), 1e-7 * std::sqrt(reference)) << "component " << c;
  }
}

// The trace as a sixth column of the same batched CG: each column runs its own recurrence, so
// the tensors are exactly those of the traceless solve plus a separate solve of the traces.
TEST(HarmonicSolver, TraceSolvedBesideTheDeviatorEqualsTwoSolvesBitwise) {
  const auto mesh = jitteredBox(12);
  std::vector<Tensor> values(mesh->vertexCount());
  std::vector<int> region;
  for (std::size_t v = 0; v < values.size(); ++v) {
    const Vec3& p = mesh->positions()[v];
    values[v] = Tensor{std::sin(3 * p.x()) + 2, std::cos(2 * p.y()) * p.z(), 0.5 * p.z(),
                       p.x() * p.y(),           std::sin(p.z() + p.x()),     0.3};
    if ((p - Vec3(0.2, -0.1, 0.1)).norm() < 0.45) region.push_back(static_cast<int>(v));
  }
  ASSERT_GT(region.size(), 50u);
  const HarmonicSolver solver = HarmonicSolver::forRegion(mesh, region);
  const SolveResult both = solver.solveWithTrace(values);
  SolveResult apart = solver.solve(values);
  std::vector<double> trace(values.size());
  for (std::size_t v = 0; v < values.size(); ++v) trace[v] = values[v].trace();
  double traceResidual = 0;
  const int traceIterations = solver.solveColumns(trace, 1, {}, &traceResidual);
  for (int v : region) {
    const double third = trace[v] / 3;
    apart.values[v].xx += third, apart.values[v].yy += third, apart.values[v].zz += third;
  }
  EXPECT_EQ(both.iterations, std::max(apart.iterations, traceIterations));
  EXPECT_EQ(both.relativeResidual, std::max(apart.relativeResidual, traceResidual));
  for (std::size_t v = 0; v < values.size(); ++v)
    ASSERT_EQ(both.values[v], apart.values[v]) << "vertex " << v;
  EXPECT_NE(both.values[region[0]].trace(), 0.0);
}

TEST(HarmonicSolver, WarmStartFromTheSolutionNeedsNoIterations) {
  const auto mesh = jitteredBox(10);
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  std::vector<Tensor> values(mesh->vertexCount());
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); v += 97) {
    fixed[v] = 1;
    values[v] = linearTensor(mesh->positions()[v] * 3.0);
  }
  const HarmonicSolver solver(mesh, fixed);
  const SolveResult cold = solver.solve(values);
  EXPECT_GT(cold.iterations, 2);
  const SolveResult warm = solver.solve(cold.values);
  EXPECT_LE(warm.iterations, 1);
  for (std::size_t v = 0; v < values.size(); ++v)
    EXPECT_LT(maxDifference(warm.values[v], cold.values[v]), 1e-9);
}

TEST(HarmonicSolver, BitwiseEqualForOneAndTwoThreads) {
  const auto mesh = test::mappedTorus(48, 7);  // 14112 tets
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  std::vector<Tensor> values(mesh->vertexCount());
  for (int v = 0; v < static_cast<int>(mesh->vertexCount()); v += 211) {
    fixed[v] = 1;
    values[v] = Tensor::fromVec5({hashUnit(v), hashUnit(v + 9), 0.5, hashUnit(v + 2), -0.3});
  }
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    SolverOptions o;
    o.reuseSetup = false;  // each run builds its own set-up
    const HarmonicSolver solver(mesh, fixed, o);
    return solver.solve(values);
  };
  const SolveResult one = run(1), two = run(2);
  EXPECT_EQ(one.iterations, two.iterations);
  ASSERT_EQ(one.values.size(), two.values.size());
  for (std::size_t v = 0; v < one.values.size(); ++v) ASSERT_EQ(one.values[v], two.values[v]) << v;
}

TEST(HarmonicSolver, SolveColumnsReproducesLinearScalars) {
  const auto mesh = jitteredBox(8);
  const int width = 3;
  std::vector<double> values(mesh->vertexCount() * width, 0.0);
  for (int v : mesh->boundaryVertices())
    for (int c = 0; c < width; ++c) values[v * width + c] = mesh->positions()[v][c] * (c + 1) - c;
  const HarmonicSolver solver(mesh, boundaryMask(*mesh), SolverOptions{1e-12, 1000, true});
  double residual = 1;
  solver.solveColumns(values, width, {}, &residual);
  EXPECT_LT(residual, 1e-11);
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v)
    for (int c = 0; c < width; ++c)
      EXPECT_NEAR(values[v * width + c], mesh->positions()[v][c] * (c + 1) - c, 1e-9);
}

TEST(HarmonicSolver, DoublePrecisionPreconditionerGivesTheSameSolution) {
  const auto mesh = jitteredBox(9);
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  std::vector<Tensor> values(mesh->vertexCount());
  for (int v : {10, 400, 700}) {
    fixed[v] = 1;
    values[v] = linearTensor(mesh->positions()[v] * 5.0);
  }
  const SolveResult a = HarmonicSolver(mesh, fixed, SolverOptions{1e-10, 1000, true}).solve(values);
  const SolveResult b =
      HarmonicSolver(mesh, fixed, SolverOptions{1e-10, 1000, false}).solve(values);
  for (std::size_t v = 0; v < values.size(); ++v)
    EXPECT_LT(maxDifference(a.values[v], b.values[v]), 1e-7);
}

/// Two boxes side by side that share no vertex: two connected components.
std::shared_ptr<const TetMesh> twoBoxes() {
  const auto a = makeBoxMesh(3, 3, 3, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Vec3> positions = a->positions();
  std::vector<TetMesh::Tet> tets = a->tets();
  const int offset = static_cast<int>(positions.size());
  for (const Vec3& p : a->positions()) positions.push_back(p + Vec3(3, 0, 0));
  for (auto t : a->tets()) {
    for (int& v : t) v += offset;
    tets.push_back(t);
  }
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

TEST(HarmonicSolver, ComponentWithoutFixedVertexIsAClearError) {
  const auto mesh = twoBoxes();
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  fixed[0] = 1;  // only the first box is anchored
  try {
    HarmonicSolver solver(mesh, fixed);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no fixed vertex"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("64 vertices"), std::string::npos) << e.what();
  }
  fixed[mesh->vertexCount() - 1] = 1;
  EXPECT_NO_THROW(HarmonicSolver(mesh, fixed));
}

TEST(HarmonicSolver, BadInputIsAClearError) {
  const auto mesh = jitteredBox(4);
  EXPECT_THROW(HarmonicSolver(mesh, std::vector<unsigned char>(3, 0)), Error);
  EXPECT_THROW(HarmonicSolver(mesh, std::vector<unsigned char>(mesh->vertexCount(), 1)), Error);
  EXPECT_THROW(HarmonicSolver(mesh, std::vector<unsigned char>(mesh->vertexCount(), 0)), Error);
  EXPECT_THROW(HarmonicSolver::forRegion(mesh, {4, 2}), Error);
  const HarmonicSolver solver(mesh, boundaryMask(*mesh));
  EXPECT_THROW(solver.solve(std::vector<Tensor>(5)), Error);
  std::vector<Tensor> values(mesh->vertexCount());
  int interior = 0;
  while (mesh->isBoundaryVertex(interior)) ++interior;
  values[interior].xx = std::nan("");  // a free vertex's initial guess
  EXPECT_THROW(solver.solve(values), Error);
  values[interior].xx = 0;
  values[mesh->boundaryVertices()[0]].yz = INFINITY;  // a fixed value the solve reads
  EXPECT_THROW(solver.solve(values), Error);
  std::vector<double> columns(mesh->vertexCount() * 7);
  EXPECT_THROW(solver.solveColumns(columns, 7), Error);
}

TEST(HarmonicSolver, CancellationStopsTheSolve) {
  const auto mesh = jitteredBox(8);
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  fixed[3] = 1;
  std::vector<Tensor> values(mesh->vertexCount());
  values[3] = linearTensor(Vec3(1, 2, 3));
  const HarmonicSolver solver(mesh, fixed);
  std::atomic<bool> cancel{true};
  EXPECT_THROW(solver.solve(values, Progress({}, &cancel)), Cancelled);
}

TEST(HarmonicSolver, MultigridHierarchyIsSmallAndCoarsens) {
  const auto mesh = test::mappedBall(17);  // 29478 tets
  std::vector<unsigned char> fixed(mesh->vertexCount(), 0);
  fixed[0] = 1;
  const HarmonicSolver solver(mesh, fixed);
  const auto& levels = solver.preconditioner().levels();
  ASSERT_GE(levels.size(), 2u);
  for (std::size_t l = 1; l < levels.size(); ++l) EXPECT_LT(levels[l].rows * 4, levels[l - 1].rows);
  EXPECT_LT(solver.preconditioner().operatorComplexity(), 1.6);
}

}  // namespace
}  // namespace tfd::core

namespace tfd::core {
namespace {

TEST(HarmonicSolver, IsolatedFreeVerticesNeedNoCoarseLevels) {
  // Free vertices with no free neighbour: the free block is diagonal, nothing can be
  // aggregated, and the solution is x_i = −Σ_j K_ij x_j / K_ii.
  const int n = 30;
  const auto mesh = makeBoxMesh(n, n, n, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<int> free;
  for (int k = 2; k < n; k += 2)
    for (int j = 2; j < n; j += 2)
      for (int i = 2; i < n; i += 2) free.push_back(i + (n + 1) * (j + (n + 1) * k));
  ASSERT_GT(free.size(), 2000u);
  std::vector<Tensor> values(mesh->vertexCount());
  for (std::size_t v = 0; v < values.size(); ++v)
    values[v] = Tensor::fromVec5({hashUnit(v), hashUnit(v + 1), hashUnit(v + 2), 0, 0.5});
  const HarmonicSolver solver = HarmonicSolver::forRegion(mesh, free);
  const SolveResult result = solver.solve(values);
  const StiffnessRows rows = assembleStiffnessRows(*mesh, free);
  for (std::size_t r = 0; r < free.size(); r += 97) {
    Tensor sum, diag;
    double kii = 0;
    for (int m = rows.matrix.start[r]; m < rows.matrix.start[r + 1]; ++m) {
      if (rows.matrix.index[m] == free[r])
        kii = rows.matrix.value[m];
      else
        sum += values[rows.matrix.index[m]].deviator() * rows.matrix.value[m];
    }
    EXPECT_LT(maxDifference(result.values[free[r]], sum * (-1.0 / kii)), 1e-8);
  }
}

}  // namespace
}  // namespace tfd::core
