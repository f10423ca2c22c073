#pragma once
// Dirichlet-constrained harmonic solve of the five tensor components (paper §5, Equation 1).
#include <memory>
#include <vector>

#include "core/progress.h"
#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

struct SolverOptions {
  double tolerance = 1e-8;  ///< relative residual ‖b − Kx‖ / ‖b‖ per component
  int maxIterations = 20000;
};

struct SolveResult {
  std::vector<Tensor> values;  ///< one per mesh vertex
  int iterations = 0;
  double relativeResidual = 0;  ///< worst of the five components
};

/// Minimises the P1 Dirichlet energy (Eq. 1) of each tensor component with the vertices marked
/// fixed held at their given values; the others are free (natural boundary condition on the
/// domain boundary). The set-up (stiffness restricted to the free vertices, preconditioner) is
/// done once in the constructor and reused by every solve while the fixed set is unchanged.
/// A region solve is the same thing with every vertex outside the region marked fixed.
/// Deterministic for any thread count.
class HarmonicSolver {
 public:
  /// `fixed[v] != 0` holds vertex v. Throws core::Error when nothing is fixed in some connected
  /// component of free vertices' mesh (the problem would have no unique solution) or when
  /// `fixed` has the wrong size.
  HarmonicSolver(std::shared_ptr<const TetMesh> mesh, std::vector<unsigned char> fixed,
                 SolverOptions options = {});
  ~HarmonicSolver();
  HarmonicSolver(HarmonicSolver&&) noexcept;
  HarmonicSolver& operator=(HarmonicSolver&&) noexcept;

  /// `values` holds the fixed values at fixed vertices (kept bitwise in the result) and the
  /// initial guess at free vertices (warm start: pass a previous solution). All five traceless
  /// components are solved together; the trace part of the input is dropped.
  SolveResult solve(std::vector<Tensor> values, const Progress& progress = {}) const;

  const TetMesh& mesh() const;
  std::size_t freeCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tfd::core
