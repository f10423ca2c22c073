#pragma once
// Curve design elements (paper §5, "Design" and "Parameterization"): tubular neighbourhoods
// around a sampled curve receive the value of the nearest sample's local linearisation.
#include "core/design/design_element.h"
#include "core/tet_mesh.h"

namespace tfd::core {

class FixedValueAccumulator;

/// Adds, for every mesh vertex inside the tube of radius `curve.radius` around the curve, the
/// value of the nearest curve point's linearisation applied to the vertex's displacement in that
/// point's frame, with a weight that falls with the distance to the curve (so overlapping tubes
/// of several curves blend). Throws core::Error naming the problem (curve outside the mesh, zero
/// radius, ...).
void applyCurveElement(const TetMesh& mesh, const CurveElement& curve,
                       FixedValueAccumulator& accumulator);

}  // namespace tfd::core
