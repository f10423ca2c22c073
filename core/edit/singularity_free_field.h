#pragma once
// Singularity-free tensor field generation (paper §6.3): inside a region M that is a
// topological ball, replace the field by one without degenerate points, keeping it unchanged
// outside M and on M's held vertices.
//
// In M the non-repeating eigenvector N (major for Linear, minor for Planar targets) is a vector
// field (core/edit/vectorise_eigenvector.h) and stays as it is, except where it turns by more
// than 30° across an edge next to a vertex where its eigenvalue nearly repeats (a
// near-degeneracy of the other type that the mesh does not resolve), or, when asked
// (`smoothEveryFastTurn`, as a removal does), wherever it turns by more than 30° across an edge:
// there the free vertices take its harmonic extension (core/edit/smooth_directions.h), since
// a field keeping such an N, with the large gaps made below, repeats an eigenvalue on the faces
// in between. A degenerate point of the new field could then only be a singularity of the
// medium eigenvector. So the medium eigenvector is
// written as an angle θ from a reference field U ⊥ N (core/edit/reference_field.h: U by
// parallel transport on the Gauss sphere over a ball order of the tets, and the jumps of the
// edges), θ is fixed on the held vertices (Equation 5) and solved inside with the jump-aware
// Laplacian (Equation 6, core/edit/angle_field.h): a continuous θ has no singularity. The major
// and minor eigenvalues of the deviator are harmonic (Equation 1) with the same held values,
// the medium one is −λ1 − λ3, and the frame (N, medium, N × medium) recombines them into
// traceless tensors. A trace, if the held values have one, is solved as one more harmonic
// scalar and added back.
//
// Eigenvalue gaps: λ1 − λ2 = 2λ1 + λ3 and λ2 − λ3 = −λ1 − 2λ3 are linear combinations of
// harmonic functions, hence harmonic; by the maximum principle they stay positive inside M when
// they are positive on the held vertices. (Discretely this holds where the cotangent weights
// are non-negative, e.g. on the structured box meshes; obtuse TetGen tets can dent it by
// rounding-level amounts near the held boundary. The report gives the smallest gaps.)
//
// Vertices: every vertex outside M and every held vertex of M keeps its tensor bitwise. A
// vertex of M that also belongs to a tet outside M is always held (changing it would change
// the field outside M), whatever `held` says. The other vertices of M are solved: the interior
// ones, and those on the domain surface (free, natural boundary condition).
// Requirements: M a topological ball (else nonBallSteps > 0 and jumps may be inconsistent),
// the non-repeating eigenvector orientable in M (no sign conflict), no degenerate point on the
// held vertices' part of the boundary, at least one held vertex.
// Deterministic for any thread count; cost proportional to M, not to the mesh.
#include <cstddef>
#include <string>
#include <vector>

#include "core/degeneracy.h"
#include "core/edit/region_complex.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/progress.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct SingularityFreeReport {
  std::size_t regionTets = 0;
  std::size_t regionVertices = 0;
  std::size_t heldVertices = 0;  ///< held (given or forced by a tet outside M)
  std::size_t freeVertices = 0;  ///< solved
  int nonBallSteps = 0;          ///< tets the reference propagation added without a ball order
  /// Region edges across which the given N turned by more than 30° next to a vertex where it
  /// is ill-defined (its eigenvalue gap under a tenth of the deviator's spread), and the free
  /// vertices around them given N's harmonic extension (core/edit/smooth_directions.h).
  int roughEdges = 0, repairedDirections = 0;
  double maxHolonomyDefect = 0;  ///< see ReferenceField
  int iterations = 0;
  double relativeResidual = 0;
  /// Whether the held vertices carry a trace beyond rounding (traceBeyondRounding()), solved as
  /// one more harmonic column; otherwise the solved tensors are traceless.
  bool traceSolved = false;
  /// Smallest eigenvalue gaps (λ1 − λ2 and λ2 − λ3 of the deviator) over the held vertices and
  /// over the solved ones.
  double heldMinGap12 = 0, heldMinGap23 = 0, freeMinGap12 = 0, freeMinGap23 = 0;
  std::string summary() const;  ///< one line for a node's info message
};

/// §6.3: a field equal to `field` on every vertex outside the region and on the region's
/// held vertices (`held[v] != 0`, v a mesh vertex index), and free of degenerate points inside
/// the region (the region must be a topological ball whose held boundary has none).
/// Throws core::Error for an empty or invalid region, `held` not one entry per mesh vertex,
/// no held vertex, a region that is not connected, or a non-repeating eigenvector that cannot
/// be oriented in it (sign conflicts: the region holds a degenerate point where that
/// eigenvector repeats). Cancellable.
TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType type,
                                 const Progress& progress = {});
/// Same, filling `report` when it is not null.
TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType type,
                                 const Progress& progress, SingularityFreeReport* report);
/// Same, on the region complex and the vectorised non-repeating eigenvector of `type` already
/// computed by the caller (`directions` of vectoriseEigenvector(field, region, type)): a
/// removal builds both once for its report and for this step. `smoothEveryFastTurn`: the free
/// vertices take N's harmonic extension around every region edge across which N turns by more
/// than 30°, not only next to a vertex where N is ill-defined (a removal asks for it: where a
/// well-defined N turns that fast across a tet, e.g. a boundary-conforming N at an edge of the
/// domain, and the gap of the repeating pair is small, the linear interpolation of the new
/// tensors repeats an eigenvalue inside the tet).
TensorField singularityFreeField(const TensorField& field, const RegionComplex& region,
                                 const VectorisedEigenvector& n, const std::vector<char>& held,
                                 DegenerateType type, const Progress& progress,
                                 SingularityFreeReport* report, bool smoothEveryFastTurn = false);

}  // namespace tfd::core
