#pragma once
// Where the held values of a region cannot give the angle field of paper §6.3 a continuous
// lift (Equation 5): degenerate points of the removal's type on the region's boundary as the
// angle method itself sees them.
//
// §6.3 writes the medium eigenvector as an angle θ about the non-repeating eigenvector N, fixed
// on the held vertices. Around a triangle (a, b, c) the medium line field turns, relative to
// parallel transport along N's great-circle arcs, by
//     k·π = Σ_edges wrap_π(∠_{N_b}(T_{a→b} m_a, m_b)) + Ω(N_a, N_b, N_c),
// k an integer: the triangle's index in half-turns (T the minimal rotation taking N_a to N_b,
// Ω the signed area of the spherical triangle, so the jumps of core/edit/reference_field.h
// cancel). k ≠ 0 marks a point where the medium eigenvector is undefined, i.e. a degenerate
// point of the removal's type. No extracted curve need pass there: the extraction looks at the
// linear interpolation of the tensors, while where N turns fast across a tet (a
// boundary-conforming field at an edge or corner of the domain surface) the transported frame
// winds although the interpolated tensors do not repeat an eigenvalue; or the point is too small
// for the mesh.
//
// Such a point on the held boundary makes the lift inconsistent: the held values of θ disagree
// by π across a "seam" of held edges, and the harmonic θ then has a singular line running from
// the seam into the region, which the re-extraction finds as a new curve or a piece of the
// target left behind. Two cases, both checked here:
//  1. a held triangle (all three vertices held) with k ≠ 0;
//  2. a surface patch (a connected piece of the region's boundary on the domain surface; its
//     rim is held) whose outward-oriented faces' indices do not sum to zero: the held loop
//     around it winds. The targets' own faces on the surface count (a one-curve target's two
//     ends cancel when they lie in one patch) but are never reported, since the region must
//     hold them.
// A removal keeps the tets around the reported faces out of its region and grows it again, as
// it does around the sign conflicts of N (core/edit/vectorise_eigenvector.h).
// Cost: proportional to the region's faces; deterministic.
#include <array>
#include <span>
#include <vector>

#include "core/edit/region_complex.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// The index in half-turns of the line field m (unit, m_i ⊥ n_i) about the unit vector field n
/// around the triangle 0 → 1 → 2 (right-handed about its normal). Throws core::Error when two
/// of the directions are (nearly) opposite.
int lineFieldIndex(const std::array<Vec3, 3>& n, const std::array<Vec3, 3>& m);

struct AngleDefects {
  /// Mesh faces whose surroundings a region should avoid, ascending: the held triangles with a
  /// non-zero index and, in every surface patch whose indices do not sum to zero, its faces
  /// with a non-zero index that no target tet holds.
  std::vector<int> faces;
  int heldTriangles = 0;      ///< held triangles with a non-zero index
  int unbalancedPatches = 0;  ///< surface patches whose indices do not sum to zero
};

/// `n`: the vectorised non-repeating eigenvector over `region` (no sign conflict); `held`: one
/// flag per mesh vertex, set on the region vertices that touch a tet outside it
/// (core/region/region_vertices.h); `targetTets`: the tets holding a target's points, ascending.
/// The medium eigenvector is the given field's.
AngleDefects angleDefects(const TensorField& field, const RegionComplex& region,
                          const VectorisedEigenvector& n, const std::vector<char>& held,
                          std::span<const int> targetTets);

}  // namespace tfd::core
