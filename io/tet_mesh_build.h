#pragma once
// Turning raw vertex and tet arrays (from a file or TetGen) into a validated TetMesh.
//
// Conventions of every tet-mesh reader (io/tetgen/node_ele.h, io/mesh/gmsh.h,
// io/vtk/vtu_reader.h), which all end in buildTetMesh:
// All readers return a validated, positively oriented core::TetMesh:
// - only tetrahedra are read; lower-dimensional elements (points, lines, triangles, quads) are
//   ignored, other volume elements (hexahedra, prisms, pyramids) are an error; second- and
//   higher-order tets keep their four corners;
// - vertices no tet uses are dropped (the others keep their file order);
// - a mesh whose tets are all negatively oriented is flipped silently; a mix is an error from
//   core::TetMesh naming the tet ("file 'x.msh': invalid tet mesh (...): tet 12 is inverted").
// Errors are core::Error naming the file and, for text, the line, what was expected and what
// was found, as for the surface readers.
#include <memory>
#include <string>
#include <vector>

#include "core/tet_mesh.h"

namespace tfd::io {

/// Builds the TetMesh of `positions` and `tets` coming from `source` (a file name or "TetGen",
/// used in messages):
/// - vertices no tet uses are dropped (the others keep their order);
/// - when every tet is negatively oriented (a consistent convention of the writer), every tet
///   is flipped (local vertices 1 and 2 swapped), silently;
/// - otherwise TetMesh validation runs, and its problems (e.g. "tet 12 is inverted") are
///   thrown as core::Error prefixed with `source`.
/// Tet indices must be in range; out-of-range indices are reported, also prefixed.
/// core::Cancelled (from `progress`, checked inside the topology build) passes through as is.
std::shared_ptr<const core::TetMesh> buildTetMesh(std::vector<core::Vec3> positions,
                                                  std::vector<core::TetMesh::Tet> tets,
                                                  const std::string& source,
                                                  const core::Progress& progress = {});

}  // namespace tfd::io
