#pragma once
// Boundary-conforming tensor values (paper §5, "Boundary-conforming tensor fields", Eq. 4).
//
// In a frame whose third axis is the unit normal N, T = [[M_B, M_BN], [M_BNᵀ, M_N]]; setting
// the tangent-normal block M_BN to zero makes N an eigenvector. In world coordinates this is
// T' = P T P + (Nᵀ T N) N Nᵀ with P = I − N Nᵀ (independent of the tangent axes chosen).
// The trace is preserved, so traceless tensors stay traceless.
#include <vector>

#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

/// T with its tangent-normal block removed; `normal` need not be unit length (a zero normal
/// returns T unchanged).
Tensor conformToNormal(const Tensor& t, const Vec3& normal);

/// For every boundary vertex v of the mesh, conformToNormal(values[v], vertex normal of v);
/// entries in mesh.boundaryVertices() order.
std::vector<Tensor> conformingBoundaryValues(const TetMesh& mesh,
                                             const std::vector<Tensor>& values);

}  // namespace tfd::core
