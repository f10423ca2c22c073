#pragma once
// Dirichlet-constrained harmonic solve of the five tensor components (paper §5, Equation 1).
//
// Method (chosen by measurement, see bench/RESULTS.md): the free-free block of the
// P1 stiffness matrix (core/solve/laplacian.h) is solved by conjugate gradients on all five
// components at once (one pass over the matrix per iteration), preconditioned by a
// smoothed-aggregation multigrid V-cycle (core/linalg/amg.h). Deterministic for any thread
// count: every parallel reduction uses fixed chunks summed in order.
#include <memory>
#include <span>
#include <vector>

#include "core/progress.h"
#include "core/solve/laplacian.h"
#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

namespace linalg {
class AmgPreconditioner;
}

struct SolverOptions {
  double tolerance = 1e-8;  ///< relative residual ‖b − Kx‖ / ‖b‖ per component
  int maxIterations = 20000;
  bool singlePrecisionPreconditioner = true;  ///< multigrid cycle in float (CG stays double)
  /// Optional: a known bound for ρ(D⁻¹A) of the free block (see linalg::AmgOptions); a solver
  /// whose free vertices are a subset of another's may pass the other's
  /// preconditioner().levels()[0].lambdaMax. 0 = estimate it.
  double lambdaMaxBound = 0;
  /// Keep the set-up (blocks, locality order, multigrid hierarchy) for the mesh in
  /// core::derivedCache() and take one kept there by an earlier solver when it is exactly the
  /// one this solver would build: same free vertices, same preconditioner options and the
  /// same matrix rows (compared entry by entry). A re-cook after a constraint value change
  /// then skips the set-up; the results are bitwise those of a fresh set-up.
  bool reuseSetup = true;
};

struct SolveResult {
  std::vector<Tensor> values;  ///< one per mesh vertex
  int iterations = 0;
  double relativeResidual = 0;  ///< worst of the five components (true residual)
};

/// Minimises the P1 Dirichlet energy (Eq. 1) of each tensor component with the vertices marked
/// fixed held at their given values; the others are free (natural boundary condition on the
/// domain boundary). The set-up (stiffness restricted to the free vertices, preconditioner) is
/// done once in the constructor and reused by every solve while the fixed set is unchanged.
/// A region solve is the same thing with every vertex outside the region fixed; its set-up
/// cost is proportional to the number of free vertices (see forRegion()).
/// Deterministic for any thread count. solve() is const and may run concurrently.
class HarmonicSolver {
 public:
  /// `fixed[v] != 0` holds vertex v. Throws core::Error when nothing is fixed in some connected
  /// component of the free vertices (the problem would have no unique solution), when
  /// `fixed` has the wrong size, or when no vertex is free.
  HarmonicSolver(std::shared_ptr<const TetMesh> mesh, std::vector<unsigned char> fixed,
                 SolverOptions options = {});
  /// Same, reusing already assembled stiffness rows: `stiffness` must contain the rows of all
  /// free vertices (e.g. assembleStiffness(mesh), shared by several solvers whose fixed sets
  /// differ).
  HarmonicSolver(std::shared_ptr<const TetMesh> mesh, std::vector<unsigned char> fixed,
                 const StiffnessRows& stiffness, SolverOptions options = {});
  /// Region solve: only `freeVertices` (ascending, unique) are free, everything else is held.
  /// Costs O(free vertices · log) to set up, independent of the mesh size.
  static HarmonicSolver forRegion(std::shared_ptr<const TetMesh> mesh,
                                  std::vector<int> freeVertices, SolverOptions options = {});
  ~HarmonicSolver();
  HarmonicSolver(HarmonicSolver&&) noexcept;
  HarmonicSolver& operator=(HarmonicSolver&&) noexcept;

  /// `values` holds the fixed values at fixed vertices (returned bitwise unchanged) and the
  /// initial guess at free vertices (warm start: pass a previous solution). The five traceless
  /// components are solved together; the free vertices receive traceless tensors (the trace
  /// part of the input is dropped).
  SolveResult solve(std::vector<Tensor> values, const Progress& progress = {}) const;
  /// solve() with the trace kept: solved as a sixth harmonic column in the same batched CG and
  /// added back (a third on each diagonal entry) at the free vertices. Each column runs its own
  /// recurrence, so the tensors are bit for bit those of solve() plus solveColumns() on the
  /// traces; one pass over the matrix per iteration instead of two solves. The iteration count
  /// is that of the slowest column.
  SolveResult solveWithTrace(std::vector<Tensor> values, const Progress& progress = {}) const;

  /// Generic form for `width` (1..6) scalar fields at once: `values` holds width numbers per
  /// vertex (vertex-major: values[v * width + c]); fixed entries are kept, free ones solved.
  /// Returns the iteration count; throws like solve().
  int solveColumns(std::span<double> values, int width, const Progress& progress = {},
                   double* relativeResidual = nullptr) const;

  const TetMesh& mesh() const;
  std::size_t freeCount() const;
  const std::vector<int>& freeVertices() const;  ///< ascending
  const linalg::AmgPreconditioner& preconditioner() const;
  /// Whether the set-up was taken from the mesh's cache (SolverOptions::reuseSetup).
  bool setupReused() const;

 private:
  HarmonicSolver();
  template <bool WithTrace>
  SolveResult solveTensors(std::vector<Tensor> values, const Progress& progress) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tfd::core
