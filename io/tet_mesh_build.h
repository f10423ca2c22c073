#pragma once
// Turning raw vertex and tet arrays (from a file or TetGen) into a validated TetMesh.
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
std::shared_ptr<const core::TetMesh> buildTetMesh(std::vector<core::Vec3> positions,
                                                  std::vector<core::TetMesh::Tet> tets,
                                                  const std::string& source);

}  // namespace tfd::io
