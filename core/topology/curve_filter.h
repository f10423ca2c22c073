#pragma once
// Selecting degenerate curves after extraction. A boundary-conforming field (paper Eq. 4) is
// block diagonal in the normal frame on the whole boundary surface, so the normal eigenvalue
// crossing a tangential one is a codimension-1 event there, and the field is nearly degenerate
// along such surface curves: extraction finds many short curves that run from a boundary face
// through the first layer of tets back to the boundary. They are genuine features of the
// discrete field, but rarely what a user designs; this lets a node set them (and curves shorter
// than a threshold) aside.
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct CurveFilter {
  double minLength = 0;       ///< drop curves whose skeletonLength is below this
  bool dropBoundary = false;  ///< drop curves that hug the boundary (hugsBoundary)
};

// Both filters look only at the curve's points on mesh faces, edges and vertices (its skeleton),
// not at the points inside tets (transition points, arc samples), so that
// ExtractOptions::arcSamples changes how a curve is drawn, never which curves pass.

/// True when every skeleton point of `curve` lies in the boundary layer of `mesh`: the simplex
/// holding it (its PointSource: face, edge or vertex) has at most one vertex off the boundary.
/// A curve without skeleton points is judged by its tets.
bool hugsBoundary(const DegenerateCurve& curve, const TetMesh& mesh);

/// The length of the polyline through the curve's skeleton points (loops: their perimeter);
/// the full length() for a curve without skeleton points.
double skeletonLength(const DegenerateCurve& curve);

/// Number of curves of `curves` that hug the boundary.
int boundaryCurveCount(const DegenerateCurves& curves, const TetMesh& mesh);

/// The curves that pass `filter`, renumbered (ids stay canonical); warnings and diagnostics
/// are kept. Throws core::Error for a negative or non-finite minLength.
DegenerateCurves filterCurves(const DegenerateCurves& curves, const TetMesh& mesh,
                              const CurveFilter& filter);

}  // namespace tfd::core
