#pragma once
// Parameters shared by the voxel exporters (ExportVDB, ExportEXR).
#include <string>
#include <vector>

#include "core/tet_mesh.h"
#include "graph/cook_context.h"
#include "graph/node_decl.h"
#include "io/volume/vdb_writer.h"

namespace tfd::nodes {

/// Declares `voxel_size` (0: automatic) and a comma-separated quantity list named `name`.
void declareVoxelParams(graph::NodeDecl& d, const std::string& quantitiesName);

/// `voxel_size`, or for 0 the mesh's longest bounding-box side / 128.
double voxelSizeOf(const graph::CookContext& c, const core::TetMesh& mesh);

/// The quantities named in the comma-separated list parameter `name` ("tensor, eigenvalues");
/// errors name the parameter.
io::VoxelQuantities quantitiesOf(const graph::CookContext& c, const std::string& name);

/// "wrote PATH: NX x NY x NZ voxels of SIZE, N active".
std::string voxelInfo(const std::string& what, const io::VoxelExportStats& stats);

}  // namespace tfd::nodes
