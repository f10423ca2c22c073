#pragma once
// The reference field U and the jumps of paper §6.3 ("Parallel transport", "Jump",
// "Propagation").
//
// The vectorised non-repeating eigenvector N maps each region vertex to the unit sphere
// (the Gauss map ϕ). U is a unit vector ⊥ N at every vertex, made by parallel transport on the
// sphere (the minimal rotation taking N_a to N_b, core/design/parallel_transport.h) over a tet
// order that keeps the visited tets a topological ball: a tet joins when it shares with the
// visited set one face and brings a new vertex, two faces and a new edge, or three faces
// (candidates sharing most faces first, breadth-first among equals, from the seed's tet). The
// new vertex takes U transported from a vertex of the tet (that edge gets jump zero); every
// other new edge (a, b) takes its jump from a triangle (a, b, c) of the tet whose other two
// edges are known, g_ab = Ω(N_a, N_b, N_c) − g_bc − g_ca.
//
// Convention: the jump g_ab from a to b is the angle about N_b from U_b to the transport of
// U_a, so an angle field θ (from U) is continuous across the edge when θ_b ≈ θ_a + g_ab
// (Equations 5 and 6), g_ba = −g_ab, and around every triangle the jumps sum exactly to the
// holonomy of transport a → b → c → a, the signed area Ω of the spherical triangle (no 2πk:
// only a ball order can guarantee that for every triangle; a wrapped angle measured per edge
// cannot). The paper's "jump" is the negative of its α; this one's sign is fixed by the tests.
//
// Inputs: mesh, region complex, N per region vertex (unit; adjacent N must not be opposite).
// Outputs below. Sequential (the order is inherently so) and deterministic; cost linear in
// the region.
#include <vector>

#include "core/edit/region_complex.h"
#include "core/tensor.h"

namespace tfd::core {

/// Signed area of the spherical triangle (a, b, c) of unit vectors, in (−2π, 2π): the angle
/// by which parallel transport around a → b → c → a turns a tangent vector about a
/// (Ω = 2 atan2(a·(b×c), 1 + a·b + b·c + c·a), the Van Oosterom–Strackee solid angle).
double sphericalTriangleArea(const Vec3& a, const Vec3& b, const Vec3& c);

struct ReferenceField {
  std::vector<Vec3> reference;  ///< U per local vertex: unit, ⊥ N
  std::vector<double> jumps;    ///< per local edge, from its lower to its higher vertex
  int seedVertex = -1;          ///< mesh id of the vertex U started from
  /// Tets that joined without keeping the visited set a ball (the region was not shellable
  /// from the seed): their new edges take the best available jump; 0 for the usual region.
  int nonBallSteps = 0;
  /// Worst |g_ab + g_bc + g_ca − Ω| over the region's triangles: rounding level, unless a tet
  /// maps to a sphere-covering tetrahedron (N winds around a point) or a non-ball step broke
  /// consistency. A diagnostic (four spherical areas per tet): 0 unless asked for.
  double maxHolonomyDefect = 0;
};

/// A jump stored for an edge (from its lower to its higher local vertex) read from local
/// vertex `from` to local vertex `to`.
inline double orientedJump(double stored, int from, int to) { return from < to ? stored : -stored; }

/// `seed` is a local vertex; U there is `seedReference` projected ⊥ N (or, when that is
/// (nearly) parallel to N, the coordinate axis least aligned with N). Throws core::Error when
/// the region is not face-connected or two adjacent directions are (nearly) opposite.
/// `measureHolonomy`: whether to compute maxHolonomyDefect.
ReferenceField referenceField(const TetMesh& mesh, const RegionComplex& region,
                              const std::vector<Vec3>& directions, int seed,
                              const Vec3& seedReference, bool measureHolonomy = true);

}  // namespace tfd::core
