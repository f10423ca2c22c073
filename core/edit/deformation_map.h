#pragma once
// The map φ of a degenerate curve deformation and the deformed field (paper §6.1, "Mapping φ"
// and "Interpolation").
//
// φ is a self-map of the region M that takes the new course γ2 to the original segment γ1
// (it assigns each vertex its pre-deformation location):
//  - envelope: every vertex v of a tet holding part of γ2 (the paper's minimal envelope) is held
//    at φ(v) = q + (v − p), p the point of γ2 closest to v and q the corresponding point of γ1
//    (γ1 and γ2 are sampled with the same number of points; between samples the
//    correspondence is linear);
//  - thick envelope (our addition): so is every vertex within D + h of γ2 (D the largest
//    distance between corresponding samples, h the mean edge length). With the minimal
//    envelope alone, a displacement of several edge lengths leaves the old course γ1 outside
//    the held tube, where the harmonic map is nearly the identity, so φ(γ1) ≈ γ1 and the old
//    curve survives next to the new one (measured on the 1M-tet box: two curves, or the curve
//    0.25 away from a 0.3 bump). The thick envelope holds γ1 too, mapped away from itself;
//  - identity on the boundary of M (vertices on a tet outside M, and M's part of the domain
//    surface) and on the tets holding the rest of the edited curve (so it does not move; the
//    minimal envelope wins over it at the joints, it wins over the thick envelope);
//  - every other vertex of M: the harmonic extension, Equation (1) on the three coordinates
//    (core/solve/harmonic_solver.h, the P1 cotangent Laplacian).
// The new tensor of each vertex that φ moves is the old field at φ(v) (barycentric in the old
// tet holding φ(v), found by a walk through face neighbours from v's tets). Fold-overs: tets of
// M whose image under φ is inverted or flat; those holding γ2 cover the new curve.
// Deterministic for any thread count (each vertex is independent; the solve is deterministic).
#include <span>
#include <vector>

#include "core/progress.h"
#include "core/region/region_vertices.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct DeformedField {
  std::vector<Tensor> values;      ///< one per mesh vertex
  std::vector<int> movedVertices;  ///< vertices whose tensor was resampled, ascending
  std::size_t envelopeVertices = 0, solvedVertices = 0, identityVertices = 0;
  std::size_t foldOvers = 0;         ///< region tets whose image is inverted or flat
  std::size_t foldOversOnCurve = 0;  ///< of which tets holding γ2
  std::size_t outsidePreimages = 0;  ///< φ(v) outside the mesh (clamped to the nearest tet)
  int iterations = 0;                ///< of the harmonic solve
};

/// Tets a polyline passes through, from samples every `step` along it, found by walks from
/// `startTet` (a tet near its first point); ascending. Throws core::Error naming the point
/// when a sample lies outside the mesh.
std::vector<int> polylineTets(const TetMesh& mesh, std::span<const Vec3> polyline, int startTet,
                              double step);

/// The tet holding p found by walking from `startTet` (−1 and clamped weights in the last tet
/// when the walk leaves the mesh); `bary` receives the barycentric weights.
int walkToPoint(const TetMesh& mesh, int startTet, const Vec3& p, Eigen::Vector4d& bary);

/// `regionTets` ascending, `rv` their vertices, `envelopeTets` the tets holding γ2 (all in the
/// region), `thick` one flag per mesh vertex of the thick envelope (interior to the region),
/// `anchor` one flag per mesh vertex held at the identity (the rest of the curve),
/// `gamma1`/`gamma2` the resampled curves (same size). Throws core::Error when the solve fails.
DeformedField deformField(const TensorField& field, std::span<const int> regionTets,
                          const RegionVertices& rv, std::span<const int> envelopeTets,
                          const std::vector<char>& thick, const std::vector<char>& anchor,
                          std::span<const Vec3> gamma1, std::span<const Vec3> gamma2,
                          const Progress& progress = {});

}  // namespace tfd::core
