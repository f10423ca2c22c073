#pragma once
// Smoothed-aggregation algebraic multigrid (Vaněk, Mandel & Brezina 1996) used as a
// preconditioner for conjugate gradients on P1 Laplacians (the harmonic solves of paper §5).
//
// Input: a symmetric positive definite CSR matrix (the free-free block of a stiffness matrix;
// it need not be an M-matrix). Set-up: strength of connection |a_ij| ≥ θ √(a_ii a_jj), greedy
// aggregation (in row order, hence deterministic), tentative prolongator of ones (the
// Laplacian's near null space is the constants), one damped-Jacobi smoothing step
// P = (I − ω D⁻¹A) P₀ with ω = 4 / (3 ρ(D⁻¹A)), Galerkin coarse matrices PᵀAP, until the
// coarsest level is small enough for a dense Cholesky factorisation.
// Apply: one V-cycle with a Chebyshev polynomial smoother in D⁻¹A (same polynomial before and
// after the coarse correction), so the preconditioner is symmetric positive definite as CG
// requires. Works on W interleaved columns at once (one pass over each matrix per step).
// All kernels are parallel and deterministic (bitwise equal for any thread count).
#include <cstddef>
#include <memory>
#include <vector>

#include "core/linalg/csr_matrix.h"

namespace tfd::core::linalg {

struct AmgOptions {
  double strengthThreshold = 0.02;  ///< θ of the strength test
  int coarsestSize = 400;           ///< dense Cholesky at or below this many rows
  int maxLevels = 12;
  int smootherDegree = 2;       ///< Chebyshev polynomial degree per smoothing
  double eigenRatio = 20;       ///< smoothing interval [λmax / ratio, λmax] of D⁻¹A
  bool singlePrecision = true;  ///< run the cycle in float (the set-up is in double)
  /// When > 0: the value used for ρ(D⁻¹A) on the finest level instead of an estimate (with
  /// its safety margin already included). A principal submatrix of a matrix has no larger
  /// ρ(D⁻¹A) (eigenvalue interlacing), so a solver for a subset of the free vertices of
  /// another can pass levels()[0].lambdaMax of the other's preconditioner.
  double fineLambdaMax = 0;
};

struct AmgLevelInfo {
  int rows = 0;
  std::size_t nonZeros = 0;
  double lambdaMax = 0;  ///< estimate of ρ(D⁻¹A) used by the smoothers
};

class AmgPreconditioner {
 public:
  /// Scratch vectors for one apply() at a time; make one per concurrent solve.
  class Workspace;

  /// Builds the hierarchy. The fine matrix is referenced, not copied (in single precision its
  /// values are, its row starts and column indices are shared): `a` must outlive the
  /// preconditioner and stay unchanged. Throws core::Error when a coarse
  /// matrix is not positive definite (the input was singular).
  explicit AmgPreconditioner(const CsrMatrix<double>& a, const AmgOptions& options = {});
  ~AmgPreconditioner();
  AmgPreconditioner(AmgPreconditioner&&) noexcept;
  AmgPreconditioner& operator=(AmgPreconditioner&&) noexcept;

  std::shared_ptr<Workspace> makeWorkspace(int width) const;
  /// z = M⁻¹ r for W interleaved columns (W = 1..6). `r` and `z` must not alias.
  template <int W>
  void apply(const double* r, double* z, Workspace& workspace) const;

  const std::vector<AmgLevelInfo>& levels() const;
  /// Σ nnz(A_l) / nnz(A_0).
  double operatorComplexity() const;
  /// Memory held by the hierarchy (matrices, prolongators, diagonals, dense factor), about.
  std::size_t bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Estimate of the largest eigenvalue of D⁻¹A (A symmetric with positive diagonal) by a few
/// Lanczos steps on D^{-1/2} A D^{-1/2} from a fixed pseudo-random start (deterministic). It
/// approaches λmax from below: callers add a safety margin.
double estimateLambdaMax(const CsrMatrix<double>& a, int iterations = 12);

}  // namespace tfd::core::linalg
