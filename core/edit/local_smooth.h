#pragma once
// Local field smoothing (paper §5, "Local field smoothing"): re-solve the harmonic problem of
// Eq. 1 inside a region R with the field outside R unchanged. "If R is strictly in the interior
// of the volume, we use the tensor values on the boundary of R ... as the boundary condition. If
// R intersects the boundary of the volume, we also use K = R ∩ ∂M as a boundary condition."
//
// Inputs: a field and a region: a sphere (center, radius), an axis-aligned box (center, size =
// edge lengths) or the tube of `radius` around the degenerate curve of the field nearest to a
// picked point (extracted with core/topology, then core/region/curve_tube.h for the tube).
// Output: a new field sharing the mesh. Free vertices = region vertices not on the domain
// boundary; every other vertex (outside R, or in R ∩ ∂M) keeps its input value bitwise. The
// free values minimise the P1 Dirichlet energy of each traceless component with the others
// fixed (so the discrete Laplacian vanishes at every free vertex, to the solver tolerance); the
// solve is warm-started from the input values. A trace, if the input has one in or around R, is
// smoothed the same way as a sixth scalar. Cost: proportional to the region (the stiffness rows
// and the solve only involve free vertices). Deterministic for any thread count.
#include <memory>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/solve/harmonic_solver.h"
#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

enum class SmoothRegionShape { Sphere, Box, Curve };

struct LocalSmoothOptions {
  SmoothRegionShape region = SmoothRegionShape::Sphere;  ///< `region`: sphere | box | curve
  Vec3 center = Vec3::Zero();                            ///< `center` (sphere, box)
  double radius = 0.25;             ///< `radius` (sphere radius; curve: tube radius)
  Vec3 size = Vec3(0.5, 0.5, 0.5);  ///< `size` (box edge lengths)
  Vec3 pick = Vec3::Zero();         ///< `pick` (curve: a point near the degenerate curve)
  /// Curve region: the field's degenerate curves when the caller already has them (they must
  /// belong to this field); null extracts them (core/topology/extract_degenerate_curves.h).
  const DegenerateCurves* curves = nullptr;
  SolverOptions solver;
};

struct LocalSmoothReport {
  std::size_t regionVertices = 0;  ///< mesh vertices inside R
  std::size_t freeVertices = 0;    ///< re-solved (R minus the domain boundary)
  std::size_t boundaryFixed = 0;   ///< R ∩ ∂M vertices held as boundary condition
  int iterations = 0;
  double relativeResidual = 0;
  double pickDistance = 0;      ///< curve region: distance from `pick` to the chosen curve
  std::string summary() const;  ///< one line for the node's info message
};

struct LocalSmoothResult {
  TensorField field;
  LocalSmoothReport report;
};

/// Throws core::Error for bad input: a radius or size that is not a positive number, a
/// non-finite center or pick, an empty region ("the sphere at (x, y, z) radius r contains no
/// mesh vertex"), or (curve region) a field without degenerate curves. Cancellable.
LocalSmoothResult localSmooth(const TensorField& field, const LocalSmoothOptions& options,
                              const Progress& progress = {});

/// The vertices of the region (ascending). Same errors as localSmooth.
std::vector<int> smoothRegionVertices(const TensorField& field, const LocalSmoothOptions& options,
                                      double* pickDistance = nullptr,
                                      const Progress& progress = {});

/// The smoothing itself for an explicit region (ascending, unique vertex ids; may be empty).
LocalSmoothResult smoothVertices(const TensorField& field, const std::vector<int>& region,
                                 const SolverOptions& solver = {}, const Progress& progress = {});

}  // namespace tfd::core
