#pragma once
// Curvature tensor of the boundary surface of a tet mesh (for paper §5, "Tensor fields from
// curvature tensor"), estimated per vertex after Rusinkiewicz, "Estimating Curvatures and Their
// Derivatives on Triangle Meshes" (3DPVT 2004).
//
// Inputs: a TetMesh; its outward-oriented boundary faces and area-weighted vertex normals.
// Method: per boundary face, the second fundamental form II_f (2×2 in a face frame) is the
// least-squares fit of II_f·e = Δn over the face's three edges e (Δn the difference of the
// vertex normals along e). Each vertex averages the forms of its faces, weighted by one third
// of the face area, after rotating each face frame so that its normal matches the vertex
// normal (the minimal rotation).
// Output: per boundary vertex a symmetric 3×3 tensor II = k1 d1d1ᵀ + k2 d2d2ᵀ that lives in
// the tangent plane (its normal component is exactly zero). Sign convention: with outward
// normals a convex surface has positive curvature (a sphere of radius r gives II = (1/r)·P).
// Deterministic (faces are accumulated in ascending order).
#include <vector>

#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

/// One tangent tensor per entry of mesh.boundaryVertices() (same order).
std::vector<Tensor> boundaryCurvatureTensors(const TetMesh& mesh);

struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;                      ///< k1 ≥ k2
  Vec3 d1 = Vec3::Zero(), d2 = Vec3::Zero();  ///< unit tangent directions
};
/// Principal curvatures and directions of a tangent curvature tensor at a vertex with unit
/// normal `normal` (the eigenpair along the normal is left out).
PrincipalCurvatures principalCurvatures(const Tensor& curvature, const Vec3& normal);

/// The paper's 2D-to-3D conversion: the curvature tensor plus `normalEigenvalue` along the
/// normal, II + λ n nᵀ, returned traceless (the deviator). The normal stays an eigenvector.
Tensor liftCurvatureTensor(const Tensor& curvature, const Vec3& normal, double normalEigenvalue);

}  // namespace tfd::core
