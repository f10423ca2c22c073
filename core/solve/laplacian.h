#pragma once
// P1 (cotangent) stiffness matrix of a tet mesh: the Hessian of the Dirichlet energy of
// Equation 1 (paper §5, "Propagation"), ∫ ½|∇ψ|² = ½ ψᵀKψ with K_ij = Σ_t V_t ∇φ_i·∇φ_j.
//
// Inputs: a TetMesh and the vertices whose rows are wanted (all, or a region's free vertices:
// the cost is proportional to the rows asked for, not to the mesh).
// Output: CSR rows with global vertex ids as columns, ascending, including every mesh
// neighbour (entries that happen to be zero are kept, so the pattern is the mesh graph).
// Guarantees: the diagonal is minus the sum of the row's off-diagonal entries (rows sum to 0),
// K_ij and K_ji are bitwise equal (both sum the same per-tet terms in ascending tet order),
// and the result is identical for any thread count. The Laplacian of TetGen meshes is not an
// M-matrix: off-diagonal entries can be positive (obtuse dihedral angles).
#include <array>
#include <span>
#include <vector>

#include "core/linalg/csr_matrix.h"
#include "core/tet_mesh.h"

namespace tfd::core {

/// Off-diagonal stiffness entries K_ij = V ∇φ_i·∇φ_j of the tet (p0, p1, p2, p3), in the
/// order of TetMesh::tetEdges: (01, 02, 03, 12, 13, 23). K_ij = −(1/6) |e_ij| cot θ_ij where
/// θ_ij is the dihedral angle at the opposite edge (the cotangent formula).
std::array<double, 6> tetStiffness(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

/// Some rows of the stiffness matrix.
struct StiffnessRows {
  std::vector<int> vertices;         ///< global vertex id of each row, ascending
  linalg::CsrMatrix<double> matrix;  ///< rows = vertices.size(), cols = mesh vertex count
};

/// Every row (vertices = 0..n−1): the full symmetric n×n stiffness matrix.
StiffnessRows assembleStiffness(const TetMesh& mesh);
/// The rows of `vertices` (ascending, unique; throws core::Error otherwise).
StiffnessRows assembleStiffnessRows(const TetMesh& mesh, std::vector<int> vertices);

/// (K u) at the rows of `rows` for a scalar per mesh vertex.
std::vector<double> applyStiffness(const StiffnessRows& rows, std::span<const double> u);

/// ∫ |∇u|² over the mesh for the piecewise-linear interpolant of u (= uᵀKu), summed per tet.
double gradientEnergy(const TetMesh& mesh, std::span<const double> u);

}  // namespace tfd::core
