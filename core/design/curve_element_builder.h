#pragma once
// Curve design element from user input (paper §5, "Design"): control points -> smooth spline ->
// evenly spaced samples (both ends included) -> twist-free frame per sample -> one local
// linearisation per sample. This is what the CurveConstraint graph node calls; its public
// parameter names are given next to each field.
//
// Frame convention (core/design/design_element.h): in a LocalLinearization the non-degenerate
// eigenvector is the frame's z axis. A sample's frame is therefore (u, v, t) · R before and after
// the user rotation R: u, v are the Bishop normals (parallel transport, Bergou et al. 2008), t
// the spline tangent, and R = rotationFromEulerDegrees(rotation) acts in the local frame, so the
// angle between the non-degenerate eigenvector and the tangent is the same all along the curve
// (the paper: "the Jacobian coefficients do not change with respect to the new local coordinate
// system").
//
// Canonical tube coordinates. The paper maps the tube to a canonical neighbourhood (Fig. 7)
// before applying the linearisation; here the displacement is measured in units of the tube
// radius: a degenerate sample's Jacobian is the pattern's (Eq. 3 defaults or the custom blocks)
// divided by `radius`. The pattern then has the same strength at the tube's surface whatever the
// model's units (a design on a mesh scaled by 1000 gives the same field), and a stronger pattern
// relative to T0 keeps the degenerate curve of the propagated, piecewise-linear field close to
// the designed one where the curve bends (the frame's turning adds a second-order term ∝ κ²h²
// in the degenerate plane; the curve moves by that term over the Jacobian's size).
//
// Closed curves and holonomy. Transporting u once around a loop brings it back rotated about the
// tangent by the holonomy angle h (the solid angle enclosed by the tangent indicatrix, mod 2π).
// The pattern in the degenerate plane is not invariant under such a rotation: turning the frame
// by φ about t multiplies the complex 2-D deviator field f(z) = α + iβ of a wedge (f = z) by
// e^{iφ} and of a trisector (f = z̄) by e^{3iφ}, so with an uncorrected frame the designed field
// would jump across the seam between the last and the first sample unless φ is a multiple of 2π
// (wedge) or 2π/3 (trisector). The builder spreads −h linearly in arc length over the loop
// (BishopOptions::distributeHolonomy), which makes the frame field periodic and twisting at a
// uniform, minimal rate, so the designed field is continuous all around the loop.
#include <optional>
#include <string_view>
#include <vector>

#include "core/design/design_element.h"

namespace tfd::core {

enum class CurveKind { Tensor, Degenerate };

/// A custom 2-D pattern: the symmetric 2x2 blocks of T_x and T_y acting on the degenerate plane
/// (paper Eq. 3: "The user can change the 2D tensor pattern inside the degenerate plane by
/// changing the 2×2 sub-blocks in T_x and T_y").
struct PatternBlocks {
  Eigen::Matrix2d tx = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d ty = Eigen::Matrix2d::Zero();
};

/// The blocks of the paper's defaults: T_x = diag(1, −1), T_y = [[0, 1], [1, 0]] for a wedge,
/// T_y negated for a trisector.
PatternBlocks defaultPatternBlocks(DegeneratePattern pattern);

/// The 2-D index sign δ = α_x β_y − α_y β_x of the pattern, with α = ½(A_uu − A_vv), β = A_uv
/// (research note §5.2): δ > 0 wedge, δ < 0 trisector, 0 unstable (neither).
double patternDelta(const PatternBlocks& blocks);

struct CurveOptions {
  std::vector<Vec3> points;  ///< `points`: control points [[x, y, z], ...]
  bool closed = false;       ///< `closed`
  double spacing = 0.05;     ///< `spacing`: distance between samples (rounded to divide the length)
  CurveKind kind = CurveKind::Degenerate;                ///< `kind`: tensor | degenerate
  DegenerateType type = DegenerateType::Linear;          ///< `type`: linear | planar
  DegeneratePattern pattern = DegeneratePattern::Wedge;  ///< `pattern`: wedge | trisector
  std::optional<PatternBlocks> customPattern;  ///< `pattern` = custom 2x2 blocks (replaces it)
  /// `eigenvalues` (kind tensor): along the frame's columns (u, v, t) · R; the traceless part is
  /// used. The default makes the tangent the major eigenvector.
  Vec3 eigenvalues = Vec3(0, -1, 1);
  Vec3 rotation = Vec3::Zero();  ///< `rotation`: Euler angles in degrees (x, then y, then z)
  double radius = 0.1;           ///< `radius`: tube radius
};

struct CurveBuildReport {
  std::size_t samples = 0;
  double length = 0;           ///< spline arc length
  double spacing = 0;          ///< even spacing actually used
  double holonomyDegrees = 0;  ///< closed curves: holonomy spread over the loop
};

/// Builds the element. Throws core::Error with the parameter's name for bad input: fewer than
/// two points, a closed curve with fewer than three distinct points, coincident consecutive
/// points, spacing ≤ 0, radius ≤ 0, non-finite values, a custom pattern that is not symmetric or
/// is neither a wedge nor a trisector (δ = 0).
CurveElement buildCurveElement(const CurveOptions& options, CurveBuildReport* report = nullptr);

}  // namespace tfd::core
