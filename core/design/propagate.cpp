#include "core/design/propagate.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/design/apply_constraints.h"
#include "core/design/boundary_conforming.h"
#include "core/error.h"
#include "core/linalg/amg.h"
#include "core/solve/harmonic_solver.h"
#include "core/solve/laplacian.h"
#include "core/surface/surface_curvature.h"

namespace tfd::core {

namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

std::string PropagateReport::summary() const {
  std::ostringstream out;
  out << designVertices << " design vertices";
  if (conflicts > 0) out << " (" << conflicts << " blended)";
  if (boundaryVertices > 0) out << ", " << boundaryVertices << " boundary vertices fixed";
  out << ", " << freeVertices << " free; solves: " << firstIterations;
  if (secondIterations > 0) out << " + " << secondIterations;
  out << " iterations (residual " << std::max(firstResidual, secondResidual) << "); "
      << totalSeconds << " s";
  if (reusedSetups > 0) out << " (" << reusedSetups << " solver set-up(s) reused)";
  return out.str();
}

PropagateResult propagate(std::shared_ptr<const TetMesh> mesh, const ConstraintSet& constraints,
                          const PropagateOptions& options, const Progress& progress) {
  if (!mesh) throw Error("propagate: no mesh");
  if (!(options.tolerance > 0) || !(options.tolerance < 1))
    throw Error("propagate: tolerance must be in (0, 1), got " + std::to_string(options.tolerance));
  if (!std::isfinite(options.normalEigenvalue))
    throw Error("propagate: normal eigenvalue is not finite");
  if (constraints.empty() && !options.curvatureBoundary)
    throw Error(
        "propagate: there is no design element, so nothing fixes any tensor value; connect a "
        "point or curve constraint, or enable the curvature boundary");
  PropagateReport report;
  Stopwatch total, clock;
  const std::size_t n = mesh->vertexCount();
  SolverOptions solverOptions;
  solverOptions.tolerance = options.tolerance;
  solverOptions.reuseSetup = options.reuseSetups;

  // (1) Design elements.
  progress.report(0.0, "design elements");
  const FixedValues design =
      constraints.empty() ? FixedValues{} : applyConstraints(*mesh, constraints);
  report.designVertices = design.vertices.size();
  report.conflicts = design.conflicts;
  std::vector<unsigned char> fixed(n, 0);
  std::vector<Tensor> values(n);
  Tensor mean;
  for (std::size_t i = 0; i < design.vertices.size(); ++i) {
    fixed[design.vertices[i]] = 1;
    values[design.vertices[i]] = design.values[i].deviator();
    mean += design.values[i].deviator();
  }
  if (!design.vertices.empty()) mean *= 1.0 / static_cast<double>(design.vertices.size());
  report.constraintSeconds = clock.lap();
  progress.throwIfCancelled();

  // (2) Stiffness matrix, shared by both solves.
  progress.report(0.05, "stiffness assembly");
  const StiffnessRows stiffness = assembleStiffness(*mesh);
  report.assemblySeconds = clock.lap();
  progress.throwIfCancelled();

  std::unique_ptr<HarmonicSolver> firstSolver;
  auto countFree = [&] {
    std::size_t free = 0;
    for (unsigned char f : fixed) free += f ? 0 : 1;
    return free;
  };

  // (3) First solve: design vertices only.
  if (!options.curvatureBoundary) {
    // Far from the design vertices the solution tends to a weighted mean of the design
    // values; starting there shortens the solve.
    for (std::size_t v = 0; v < n; ++v)
      if (!fixed[v]) values[v] = mean;
    report.freeVertices = countFree();
    if (report.freeVertices > 0) {
      progress.report(0.1, "harmonic solve");
      firstSolver = std::make_unique<HarmonicSolver>(mesh, fixed, stiffness, solverOptions);
      report.reusedSetups += firstSolver->setupReused();
      report.firstSetupSeconds = clock.lap();
      SolveResult first = firstSolver->solve(std::move(values), progress);
      values = std::move(first.values);
      report.firstIterations = first.iterations;
      report.firstResidual = first.relativeResidual;
      report.firstSolveSeconds = clock.lap();
    }
    if (!options.boundaryConforming) {
      report.totalSeconds = total.lap();
      progress.report(1.0, "done");
      return {TensorField(mesh, std::move(values)), report};
    }
  }

  // (4) Boundary values: conforming (Eq. 4) or from the curvature tensor.
  progress.report(0.5, "boundary values");
  const auto& boundary = mesh->boundaryVertices();
  const auto& normals = mesh->vertexNormals();
  std::vector<Tensor> curvature;
  if (options.curvatureBoundary) curvature = boundaryCurvatureTensors(*mesh);
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const int v = boundary[i];
    if (fixed[v]) continue;  // design values win
    values[v] = options.curvatureBoundary
                    ? liftCurvatureTensor(curvature[i], normals[v], options.normalEigenvalue)
                    : conformToNormal(values[v], normals[v]).deviator();
    fixed[v] = 1;
    ++report.boundaryVertices;
  }
  report.boundarySeconds = clock.lap();
  progress.throwIfCancelled();

  report.freeVertices = countFree();
  if (report.freeVertices > 0) {
    progress.report(0.55, "boundary-conforming solve");
    // The second free set is a subset of the first: its ρ(D⁻¹A) is bounded by the first's.
    SolverOptions secondOptions = solverOptions;
    if (firstSolver)
      secondOptions.lambdaMaxBound = firstSolver->preconditioner().levels()[0].lambdaMax;
    firstSolver.reset();
    const HarmonicSolver solver(mesh, fixed, stiffness, secondOptions);
    report.reusedSetups += solver.setupReused();
    report.secondSetupSeconds = clock.lap();
    SolveResult second = solver.solve(std::move(values), progress);
    values = std::move(second.values);
    report.secondIterations = second.iterations;
    report.secondResidual = second.relativeResidual;
    report.secondSolveSeconds = clock.lap();
  }
  report.totalSeconds = total.lap();
  progress.report(1.0, "done");
  return {TensorField(mesh, std::move(values)), report};
}

}  // namespace tfd::core
