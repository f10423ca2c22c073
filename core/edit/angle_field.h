#pragma once
// The angle field of paper §6.3 ("Conversion"): the medium eigenvector as an angle θ from the
// reference field U, fixed on the held vertices (Equation 5) and solved elsewhere in the region
// with the Laplacian that accounts for the jumps (Equation 6).
//
// Equation 6 at a free vertex i with neighbours j: Σ_j w_ij (θ_j − θ_i − g_ij) = 0, w_ij the
// cotangent weights (−K_ij of the P1 stiffness, core/solve/laplacian.h). It is the minimum of
// the Dirichlet energy Σ w_ij (θ_j − θ_i − g_ij)² over the edges, i.e. K_FF θ_F = r with
// r_i = Σ_j K_ij g_ij − Σ_{j held} K_ij θ_j. With zero jumps it is Equation 1 (the harmonic
// solve of §5), which is how the eigenvalues are solved alongside θ, as further columns.
// Solved by conjugate gradients with the smoothed-aggregation multigrid of core/linalg, all
// columns at once; deterministic for any thread count. Cost proportional to the region.
#include <memory>
#include <vector>

#include "core/edit/region_complex.h"
#include "core/progress.h"
#include "core/tet_mesh.h"

namespace tfd::core {

/// Equation 5 over the region's edges. `raw` holds, per local vertex, an angle known modulo
/// `period` (π for the medium eigenvector, a line); only held entries are read. From the first
/// held vertex, each vertex reached from an assigned neighbour a is given
/// θ_b = raw_b + k·period with k the integer that brings it nearest θ_a + g_ab (so that
/// |θ_b − θ_a − g_ab| ≤ period / 2) when held, or the prediction θ_a + g_ab when free (a warm
/// start for the solve). Held vertices are always reached before free ones (a 0-1 breadth-first
/// order), so a connected held set is lifted along held edges only. Returns θ per local vertex.
std::vector<double> liftAngles(const RegionComplex& region, const std::vector<char>& held,
                               const std::vector<double>& raw, const std::vector<double>& jumps,
                               double period);

struct JumpSolveOptions {
  double tolerance = 1e-10;  ///< relative residual per column
  int maxIterations = 5000;
};

struct JumpSolveResult {
  int freeVertices = 0;
  int iterations = 0;
  double relativeResidual = 0;
};

/// K_FF of Equation 6 for one region and held set, with its multigrid: built once, then solved
/// for any jumps and columns. It depends only on the mesh, the region and which vertices are
/// held, so it can be built while the jumps are still being computed (singularity_free_field).
/// Throws core::Error when a free vertex has a tet outside the region, or when a connected set
/// of free vertices has no held neighbour (no unique solution). Keeps a reference to `region`,
/// which must outlive it.
class JumpLaplacian {
 public:
  /// Whether the constructor verifies the conditions on `held` above.
  enum class HeldCheck {
    Verify,   ///< throws core::Error when they fail
    Assumed,  ///< the caller guarantees them (the singularity-free field holds every vertex on a
              ///< tet outside its region, which is connected and has a held vertex)
  };
  JumpLaplacian(const TetMesh& mesh, const RegionComplex& region, const std::vector<char>& held,
                const Progress& progress = {}, HeldCheck check = HeldCheck::Verify);
  ~JumpLaplacian();
  JumpLaplacian(JumpLaplacian&&) noexcept;

  /// Solves for `width` (1..4) columns at the free vertices (`held[i] == 0`, i local).
  /// `values` holds width numbers per local vertex (vertex-major): held entries are kept, free
  /// ones are the initial guess and receive the solution. `jumps` holds width numbers per local
  /// edge (from its lower to its higher vertex), or one: the first column's, the others having
  /// none. Throws core::Error when the sizes do not match the region or the solver does not
  /// converge.
  JumpSolveResult solve(const std::vector<double>& jumps, std::vector<double>& values, int width,
                        const JumpSolveOptions& options = {}, const Progress& progress = {}) const;

 private:
  struct System;
  const RegionComplex& region_;
  std::unique_ptr<System> system_;
};

/// JumpLaplacian(mesh, region, held).solve(jumps, values, width, options): Equation 6 solved
/// once. Every tet around a free vertex must be a region tet.
JumpSolveResult solveJumpLaplacian(const TetMesh& mesh, const RegionComplex& region,
                                   const std::vector<char>& held, const std::vector<double>& jumps,
                                   std::vector<double>& values, int width,
                                   const JumpSolveOptions& options = {},
                                   const Progress& progress = {});

}  // namespace tfd::core
