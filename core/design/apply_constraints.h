#pragma once
// From design elements to fixed vertices (paper §5, "Design"): "the design elements are used
// to generate tensor values at a set of vertices in the mesh, usually the vertices of the
// tetrahedrons that contain the design elements".
//
// Input: a mesh and the ConstraintSet of a graph (point and curve elements, in input order).
// Output: FixedValues (ascending vertex ids, blended values, counts).
// Rules: a point element fixes the 4 vertices of the tet that contains it, and also every
// vertex within its support radius max(radius, radiusEdges × mean edge length) when that is
// > 0; each such vertex gets field.evaluate(vertex
// position) (Equation 2 at the vertex). Curves go through applyCurveElement
// (core/design/curve_constraint.h). Where several elements claim a vertex their values are
// blended with weights blendWeight(d, ε) (d = distance from the vertex to the element, ε =
// kCurveBlendEpsilon × mean edge length) and the vertex is counted as a conflict.
// Errors (core::Error) name the element: "point element 2 at (x, y, z) is outside the mesh".
// Deterministic.
#include "core/design/design_element.h"
#include "core/design/fixed_values.h"
#include "core/tet_mesh.h"

namespace tfd::core {

FixedValues applyConstraints(const TetMesh& mesh, const ConstraintSet& constraints);

/// Adds one point element's contributions (the `index` is only used in error messages).
void applyPointElement(const TetMesh& mesh, const PointElement& element, int index,
                       FixedValueAccumulator& accumulator);

}  // namespace tfd::core
