#pragma once
// Repair of the non-repeating eigenvector N where it turns too fast across a region edge
// (paper §6.3 keeps N as it is in the region M; here only where it is smooth).
//
// N of a removal is the major (linear targets) or minor (planar targets) eigenvector of the
// given field, vectorised in M. Where the given field is nearly degenerate of the other type
// (λ1 ≈ λ2 for a linear target: a degenerate point the mesh does not resolve into a curve),
// N turns by up to 90° between neighbouring vertices. §6.3 then makes the eigenvalue gaps
// harmonic, hence large, and the new field, which keeps that N, has a real degenerate point on
// the faces between such vertices: the linear interpolation of tensors whose non-repeating
// eigenvectors are 90° apart repeats an eigenvalue in between. So around the rough edges (N
// turning by more than `maxTurn` with a `weak` end, one whose given N is ill-defined: its
// eigenvalue nearly repeats), out to `rings` vertex rings, the free vertices take the
// harmonic extension of N (Equation 1, the cotangent Laplacian, per component, the other
// vertices held), normalised: the smoothest field with N's values around the patch. The held
// vertices keep their N (their tensors do not change). Any smooth nowhere-zero N serves §6.3:
// the reference field, the angle θ and the recombination only need N continuous.
// A fast but well-defined turn (no weak end) is left alone: §6.3 handles it with the jumps,
// and a harmonic extension over a large patch could give N a zero. A caller that marks every
// vertex weak repairs every fast turn: a removal does (core/edit/singularity_free_field.h),
// since a boundary-conforming N turning by 45–70° inside a tet at an edge of the domain, next
// to a small gap of the repeating pair, left a piece of the target there (the verification
// still judges the result, a zero of N included).
// Deterministic for any thread count; the cost follows the repaired patch (plus a pass over
// the region's edges).
#include <vector>

#include "core/edit/region_complex.h"
#include "core/progress.h"
#include "core/tet_mesh.h"

namespace tfd::core {

struct DirectionRepair {
  std::vector<Vec3> directions;  ///< unit, one per region vertex (the input where not solved)
  int roughEdges = 0;  ///< region edges with a weak end across which N turned by more than maxTurn
  int solvedVertices = 0;    ///< free vertices given the harmonic extension
  double maxTurnBefore = 0;  ///< largest turn of N across a region edge, radians
};

/// `directions`: unit, vectorised (neighbours agree in sign), one per local vertex of `region`;
/// `held`, `weak`: one flag per local vertex (held vertices keep their direction). Throws
/// core::Error when the sizes do not match the region.
DirectionRepair repairRoughDirections(const TetMesh& mesh, const RegionComplex& region,
                                      const std::vector<Vec3>& directions,
                                      const std::vector<char>& held, const std::vector<char>& weak,
                                      double maxTurn, int rings, const Progress& progress = {});

}  // namespace tfd::core
