#pragma once
// Preconditioned conjugate gradients on W right-hand sides at once ("batched" CG: each
// column runs its own CG recurrence, but every iteration makes one pass over the matrix and
// one multigrid V-cycle for all columns together).
//
// Input: SPD CSR matrix A, right-hand sides b and initial guesses x (W interleaved columns),
// an AMG preconditioner of A. Output: x with ‖b_c − A x_c‖ ≤ tolerance · ‖b_c‖ for every
// column c (when ‖b_c‖ = 0, relative to the initial residual), or an error. A column stops
// iterating as soon as it has converged. Deterministic for any thread count (dot products
// use fixed chunks summed in order). Checks progress.throwIfCancelled() every iteration.
#include "core/linalg/amg.h"
#include "core/linalg/csr_matrix.h"
#include "core/progress.h"

namespace tfd::core::linalg {

struct CgOptions {
  double tolerance = 1e-8;
  int maxIterations = 1000;
};

struct CgResult {
  int iterations = 0;
  double relativeResidual = 0;  ///< worst column, from the true residual b − Ax at the end
  bool converged = false;
};

/// Solves A x = b for W = 1..6 columns. Throws core::Error when A turns out not to be
/// positive definite or when maxIterations is reached without convergence (the message
/// gives the residual reached).
template <int W>
CgResult blockPcg(const CsrMatrix<double>& a, const double* b, double* x,
                  const AmgPreconditioner& preconditioner, const CgOptions& options,
                  const Progress& progress);

}  // namespace tfd::core::linalg
