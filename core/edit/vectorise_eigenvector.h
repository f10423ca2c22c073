#pragma once
// Vectorising the non-repeating eigenvector in a region (paper §6.2, "Step 2"; §6.3): "We
// first choose a vertex in the region M and arbitrarily choose a forward direction from two of
// its unit non-repeating eigenvectors. We then parallel transport this vector to all the other
// vertices in M and use it to choose the forward direction of each of the non-repeating
// eigenvectors." In a simply connected region where the eigenvector's line field has no
// singularity it is a vector field (Markus 1955), and this orientation finds it.
//
// Inputs: a field, the region's tets, and the L/P type of the degenerate points the edit is
// about. Output: one unit direction per region vertex. Transport in R³ is the identity, so a
// vertex takes the sign that agrees with the already oriented neighbour it is reached from.
// When some orientation makes every region edge agree (positive dot product: the usual case),
// it is the only one, whatever the traversal; a breadth-first one finds it. Otherwise vertices
// are reached along a maximum spanning tree of the weights |e_u·e_v| (Prim's order, ties by
// vertex id): signs are decided across the best-aligned edges first, so the disagreeing edges
// are the least aligned ones. The seed is the vertex whose eigenvalue is most isolated
// (relative to ‖A‖), oriented so its largest component is positive. Deterministic for any
// thread count (the eigen-decompositions and checks run in parallel, one slot per vertex; the
// traversals are sequential).
#include <vector>

#include "core/degeneracy.h"
#include "core/edit/region_complex.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// Eigenvalues (descending) and the medium eigenvector of one decomposition: half its bytes.
struct ValuesAndMedium {
  Vec3 values;
  Vec3 medium;
  static ValuesAndMedium of(const EigenDecomposition& d) { return {d.values, d.vectors.col(1)}; }
};

/// Which eigenvector does not repeat at a degenerate point of `type`: the major one for
/// Linear (λ2 = λ3), the minor one for Planar (λ1 = λ2).
/// The non-repeating eigenvector made a vector field over the vertices of `regionTets` by
/// parallel transport from a seed vertex: each vertex's sign agrees with an already oriented
/// neighbour. Throws core::Error when the region is not connected.
struct VectorisedEigenvector {
  std::vector<int> vertices;     ///< region vertices, ascending
  std::vector<Vec3> directions;  ///< unit, one per entry of `vertices`
  /// Per entry of `vertices`: what the singularity-free field and the angle defects read of
  /// the eigen-decomposition of the field's deviator there (whose non-repeating column is the
  /// direction, up to sign).
  std::vector<ValuesAndMedium> eigen;
  int signConflicts = 0;  ///< region edges whose two directions disagree in sign (0 when the
                          ///< region holds no degenerate point)
  int seed = -1;          ///< mesh id of the seed vertex
  /// Mesh ids of the edges counted in signConflicts, ascending. A region loop whose signs
  /// cannot agree encircles a point where this eigenvector repeats; these edges form the cut
  /// where the tree's signs flip, which runs from that point (a degenerate point of the other
  /// type, extracted as a curve or too small for the mesh to resolve) along the least aligned
  /// edges, so it starts next to it.
  std::vector<int> conflictEdges;
};

/// Column of EigenDecomposition::vectors that does not repeat at a degenerate point of `type`
/// (0, the major eigenvector, for Linear; 2, the minor one, for Planar).
int nonRepeatingColumn(DegenerateType type);

/// Throws core::Error for an empty region, a tet id out of range, or a region whose vertices
/// are not connected through its edges.
VectorisedEigenvector vectoriseEigenvector(const TensorField& field,
                                           const std::vector<int>& regionTets, DegenerateType type);
/// The same on a region complex already built (core/edit/region_complex.h) of `field`'s mesh.
VectorisedEigenvector vectoriseEigenvector(const TensorField& field, const RegionComplex& region,
                                           DegenerateType type);

}  // namespace tfd::core
