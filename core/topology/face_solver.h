#pragma once
// Every degenerate point of a linearly interpolated traceless tensor field on one triangle
// (algorithms note §3.1, "conic intersection").
//
// Method. With A(s,t) = T0 + s T1 + t T2 (T0 = corner a, T1 = b − a, T2 = c − a), a point is
// degenerate with non-degenerate eigenvector v iff A(s,t) = σ b(v). Let N1, N2 span the
// orthogonal complement of span{T0,T1,T2} in the 5-D traceless space; then b(v) lies in the span
// iff vᵀN1v = vᵀN2v = 0: the intersection of two conics of ℝP², at most 4 points. One
// best-conditioned member of the pencil is parameterised as an ellipse v(θ); the other conic
// restricted to it is a trigonometric polynomial of degree 2 in θ, whose real roots come from a
// quartic in tan(θ/2) split into monotone pieces (trig_roots.h). Each root gives (α, β, γ) with
// b(v) = α T0 + β T1 + γ T2, so (s, t) = (β, γ)/α and σ = 1/α. Every point is then polished by
// Newton's method on the square 5×5 system A(s,t) − σ b(v) = 0 in (s, t, σ, v ∈ S²), which gives
// full double precision even when the pencil is badly conditioned.
//
// Guarantees. Points are returned with barycentric coordinates ≥ −edgeTolerance; tolerances are
// relative (the corners are scaled by their largest Frobenius norm). Situations where the
// points are not isolated or not reliable are reported as flags instead of guessed:
// a degenerate pencil (the conics share a component, e.g. block-diagonal fields with
// T13 = T23 ≡ 0, where a whole curve of the face plane is degenerate), linearly dependent
// corner tensors, near-double roots (the curve grazes the face), points within edgeTolerance of
// an edge or corner. The caller resolves those with a deterministic perturbation.
#include <array>

#include "core/tensor.h"

namespace tfd::core::topology {

/// One degenerate point on a face.
struct FacePoint {
  Vec3 barycentric = Vec3::Zero();   ///< weights of the corners (a, b, c), summing to 1
  Vec3 eigenvector = Vec3::UnitZ();  ///< unit non-degenerate eigenvector v
  double sigma = 0;  ///< A = σ b(v) in units of the face scale: σ > 0 linear, σ < 0 planar
};

/// Why a face needs the non-generic fallback (bit flags).
enum FaceFlag : unsigned {
  kFaceZero = 1u << 0,              ///< all corner tensors vanish (nothing to find; no fallback)
  kFaceRankDeficient = 1u << 1,     ///< corner tensors linearly dependent (e.g. constant face)
  kFaceDegeneratePencil = 1u << 2,  ///< the two conics share a component
  kFaceTangency = 1u << 3,          ///< near-double root: the curve grazes the face plane
  kFaceNearEdge = 1u << 4,          ///< a point lies on an edge or corner within tolerance
  kFacePolishFailed = 1u << 5,      ///< Newton polishing did not converge for a point
};
inline constexpr unsigned kFaceNeedsFallback =
    kFaceRankDeficient | kFaceDegeneratePencil | kFaceTangency | kFaceNearEdge | kFacePolishFailed;

struct FaceSolution {
  std::array<FacePoint, 4> points{};
  int count = 0;
  unsigned flags = 0;
};

struct FaceSolverOptions {
  /// Barycentric tolerance: points with a coordinate below −edgeTolerance are outside; those
  /// within ±edgeTolerance of an edge are kept and flagged kFaceNearEdge.
  double edgeTolerance = 1e-10;
};

/// Degenerate points of the field interpolated linearly from the corner tensors a, b, c (their
/// trace is ignored). Deterministic; no allocation.
FaceSolution solveFace(const Tensor& a, const Tensor& b, const Tensor& c,
                       const FaceSolverOptions& options = {});

}  // namespace tfd::core::topology
