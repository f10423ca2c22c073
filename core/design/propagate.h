#pragma once
// Tensor field propagation (paper §5): design elements fix tensor values at some vertices and
// the five traceless components are propagated harmonically (Equation 1) to the others;
// optionally a second solve makes the field boundary-conforming (Equation 4), or the boundary
// values come from the surface's curvature tensor ("Tensor fields from curvature tensor").
//
// Stages: (1) applyConstraints -> design vertices and values; (2) stiffness assembly, once,
// shared by both solves; (3) unless curvatureBoundary: a harmonic solve with the design
// vertices fixed and natural boundary conditions; (4) boundaryConforming: every boundary vertex
// that is not a design vertex is fixed to its value from (3) with the tangent-normal block set
// to zero, and the harmonic solve is repeated (warm-started from (3)); curvatureBoundary: the
// boundary vertices are fixed to the lifted curvature tensor (normalEigenvalue along the
// normal) instead, and one solve runs with design and boundary vertices fixed.
// Design vertices always keep their design values. The result is traceless and
// deterministic for any thread count.
#include <memory>
#include <string>

#include "core/design/design_element.h"
#include "core/progress.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct PropagateOptions {
  bool boundaryConforming = true;  ///< second solve with conforming boundary values (Eq. 4)
  bool curvatureBoundary = false;  ///< boundary values from the surface curvature tensor
  double normalEigenvalue = 0;     ///< curvatureBoundary: eigenvalue along the normal
  double tolerance = 1e-8;         ///< relative residual of each solve
  /// Keep the solvers' set-ups with the mesh and reuse them when a later propagation solves
  /// the same matrices (same mesh object, same fixed vertices): SolverOptions::reuseSetup.
  bool reuseSetups = true;
};

struct PropagateReport {
  std::size_t designVertices = 0;    ///< vertices fixed by design elements
  std::size_t conflicts = 0;         ///< of these, claimed by more than one element
  std::size_t boundaryVertices = 0;  ///< boundary vertices fixed in the last solve (0 if none)
  std::size_t freeVertices = 0;      ///< free vertices of the last solve
  int firstIterations = 0, secondIterations = 0;
  /// Solver set-ups taken from the mesh's cache (an earlier propagation of the same mesh with
  /// the same fixed vertices; HarmonicSolver, SolverOptions::reuseSetup): 0, 1 or 2.
  int reusedSetups = 0;
  double firstResidual = 0, secondResidual = 0;
  // Wall-clock seconds per stage.
  double constraintSeconds = 0, assemblySeconds = 0, firstSetupSeconds = 0, firstSolveSeconds = 0,
         boundarySeconds = 0, secondSetupSeconds = 0, secondSolveSeconds = 0, totalSeconds = 0;
  std::string summary() const;  ///< a few lines for the node's info message
};

struct PropagateResult {
  TensorField field;
  PropagateReport report;
};

/// Throws core::Error when nothing fixes any value (no design element and no curvature
/// boundary), for design elements outside the mesh, or when a connected part of the mesh has
/// no fixed vertex. Cancellable through `progress`.
PropagateResult propagate(std::shared_ptr<const TetMesh> mesh, const ConstraintSet& constraints,
                          const PropagateOptions& options = {}, const Progress& progress = {});

}  // namespace tfd::core
