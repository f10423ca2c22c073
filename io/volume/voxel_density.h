#pragma once
// Scalar measures of a tensor field for voxel exports: the `density` grid of a VDB file (a fog
// volume, so Blender and Houdini render it as imported) and the R, G, B preview channels of
// EXR slices. Every measure lies in [0, 1] and is computed from the tensor interpolated at the
// voxel centre.
#include <array>

#include "core/tensor.h"
#include "core/tensor_field.h"
#include "io/volume/voxel_quantities.h"

namespace tfd::io {

enum class VoxelDensity {
  None,        ///< no density grid / no preview
  Degeneracy,  ///< closeness to degeneracy (degeneracyCloseness): 1 on degenerate tensors
  Anisotropy,  ///< ‖A‖ / max over the mesh vertices of ‖A‖ (A the deviator)
};

/// Closeness of a tensor to degeneracy by its Lode angle (paper §3: degenerate tensors have a
/// repeated eigenvalue). The deviator's mode μ = 3√6 det(A/‖A‖) = cos 3θ, θ ∈ [0, π/3] the Lode
/// angle; θ = 0 is linear-degenerate (λ2 = λ3), θ = π/3 planar-degenerate (λ1 = λ2), θ = π/6
/// neutral (λ2 = 0). Returns (2/π)|asin μ| = 1 − (angular distance to the nearest degenerate
/// tensor)/(π/6): 1 on degenerate tensors, 0 on neutral ones, linear in the angle. A zero
/// deviator gives 0.
double degeneracyCloseness(const core::Tensor& t);

/// The VoxelScalarFunction of `measure` for `field` (nullptr function for None).
VoxelScalarFunction voxelDensityFunction(VoxelDensity measure, const core::TensorField& field);

/// The preview colour map, a value v ∈ [0, 1] (clamped) to linear RGB in [0, 1]: piecewise
/// linear through dark blue (0.05, 0.05, 0.35) at 0, teal (0.0, 0.55, 0.6) at ⅓, yellow-green
/// (0.75, 0.85, 0.15) at ⅔ and light yellow (1.0, 0.95, 0.6) at 1 — dark to light, so a grey
/// conversion still orders the values.
std::array<float, 3> previewColour(double v);

}  // namespace tfd::io
