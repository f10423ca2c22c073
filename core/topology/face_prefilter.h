#pragma once
// Conservative tests that prove a triangle of a piecewise-linear traceless field holds no
// degenerate point, so the exact face solver only runs where it can find something.
//
// Both tests may keep a face without points, and never drop a face with one:
//  - eigen-gap test: the Frobenius distance from a traceless A to the nearest degenerate tensor
//    is min(λ1−λ2, λ2−λ3)/√2 (Wielandt–Hoffman). Every tensor on the face lies within
//    max_j ‖T_j − T_i‖ of corner i, so if a corner's distance exceeds that radius the face is
//    clean; more generally, the face is clean when the three balls of radius gap_i around the
//    corner tensors cover the (flat) triangle of tensors, checked exactly in its plane.
//    Costs tens of flops per face given per-vertex gaps.
//  - Bernstein test (algorithms note §3.3-2): each Zheng–Pang cubic fᵢ restricted to the face
//    is a homogeneous cubic in barycentric coordinates; its 10 Bernstein coefficients are polar
//    forms of fᵢ at the corner tensors. If all coefficients of one fᵢ have one strict sign, fᵢ
//    cannot vanish on the face.
#include "core/tensor.h"

namespace tfd::core::topology {

/// min(λ1−λ2, λ2−λ3)/√2 of the deviator of t, lowered by a margin that covers the rounding of
/// the closed-form eigenvalues, so it never overestimates the distance to the degenerate set.
double degeneracyDistanceLowerBound(const Tensor& t);

/// True when the balls of radius gap_i around the corner tensors cover the triangle they span
/// (in particular when one corner's bound exceeds its distance to the other two): then no
/// tensor on the face is degenerate. `t` are traceless corner tensors, `gap` their
/// degeneracyDistanceLowerBound values.
bool gapExcludesFace(const Tensor* const t[3], const double gap[3]);

/// True when one Zheng–Pang function has Bernstein coefficients of a single strict sign on the
/// face with corner tensors a, b, c (any trace). Scale-free.
bool bernsteinExcludesFace(const Tensor& a, const Tensor& b, const Tensor& c);

}  // namespace tfd::core::topology
