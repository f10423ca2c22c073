#pragma once
// The tets a degenerate curve passes through, from where its points came from
// (DegenerateCurve::sources: a face, edge or vertex of the mesh, or the inside of a tet), with no
// point location. Used to mark curves on the mesh (ExportVTU's cell arrays, the viewport).
#include <vector>

#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

/// The tets holding a curve point's source: the one or two tets of a face, the tets around an
/// edge or a vertex, or the tet itself; ascending.
std::vector<int> tetsOfSource(const TetMesh& mesh, const PointSource& source);

/// One tet per segment of the curve, in order: segment i joins points i and i + 1, and a closed
/// curve of three or more points has the closing segment last. The tet is the lowest-numbered
/// one that holds both ends' sources (so it holds the whole segment); −1 when the two sources
/// share no tet (only for curves not extracted from this mesh).
std::vector<int> segmentTets(const TetMesh& mesh, const DegenerateCurve& curve);

}  // namespace tfd::core
