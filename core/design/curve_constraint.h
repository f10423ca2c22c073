#pragma once
// Curve design elements (paper §5, "Design" and "Parameterization"): tubular neighbourhoods
// around a sampled curve receive the value of the nearest curve point's local linearisation.
//
// Inputs: a mesh, a CurveElement (samples with frames and linearisations, open or closed, tube
// radius) and the accumulator that blends the fixed values of all design elements.
// Output: one (vertex, value, weight) contribution per tube vertex, added in ascending vertex
// order (deterministic), and a short report.
// Guarantees: the tube is the set of vertices within `radius` of the sampled polyline, reached
// from the curve through the volume (see core/region/curve_tube.h for the distance used). The
// value at a tube vertex v is the linearisation at its closest polyline point q, interpolated
// between the two neighbouring samples (origin q, frame by geodesic interpolation of the two
// sample frames on SO(3), T0 and Jacobian linearly), evaluated at v (Eq. 2: displacement v − q
// in the frame at q). On a straight run of identical samples the fixed values are therefore an
// exactly linear field whose degenerate curve is the polyline itself. The weight is
// blendWeight(d, ε) (core/design/fixed_values.h), ε = kCurveBlendEpsilon × mean edge length, so
// where tubes of several curves overlap, a vertex closer to one curve takes more of its value.
#include <cstddef>

#include "core/design/design_element.h"
#include "core/tet_mesh.h"

namespace tfd::core {

class FixedValueAccumulator;

/// ε of the blending weight, as a fraction of the mesh's mean edge length.
inline constexpr double kCurveBlendEpsilon = 0.1;

struct CurveApplyReport {
  std::size_t tubeVertices = 0;  ///< vertices that received a value from this curve
  std::size_t shared = 0;        ///< of these, vertices some earlier element had already claimed
  double maxDistance = 0;        ///< largest vertex-to-curve distance inside the tube
};

/// Adds, for every mesh vertex inside the tube of radius `curve.radius` around the curve, the
/// value of the nearest curve point's linearisation applied to the vertex's displacement in that
/// point's frame, with a weight that falls with the distance to the curve (so overlapping tubes
/// of several curves blend). Throws core::Error naming the problem: fewer than two samples
/// (three when closed), a radius that is not a positive number, a sample frame that is not a
/// rotation, a curve sample outside the mesh, or no mesh vertex in the tube.
CurveApplyReport applyCurveElement(const TetMesh& mesh, const CurveElement& curve,
                                   FixedValueAccumulator& accumulator);

/// The linearisation at parameter t ∈ [0, 1] between samples a and b, with origin `origin`:
/// frame a·exp(t·log(aᵀb)) (geodesic on SO(3)), value and Jacobian (1 − t)·a + t·b.
LocalLinearization interpolateLinearization(const LocalLinearization& a,
                                            const LocalLinearization& b, double t,
                                            const Vec3& origin);

}  // namespace tfd::core
