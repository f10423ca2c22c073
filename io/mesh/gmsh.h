#pragma once
// Gmsh .msh tet-mesh files (ASCII, format 2.x and 4.x).
// Every tet-mesh reader follows the conventions of io/tet_mesh_build.h.
#include <filesystem>
#include <memory>

#include "core/tet_mesh.h"

namespace tfd::io {

/// Gmsh ASCII .msh, format 2.x or 4.x ($MeshFormat says which). Node tags may be sparse and
/// in any order (they are mapped); 4.x entity blocks and parametric coordinates are handled;
/// $Entities, $PhysicalNames and other sections are skipped. Binary .msh is refused.
std::shared_ptr<const core::TetMesh> readGmsh(const std::filesystem::path& path);

enum class GmshVersion { V2, V4 };
/// Writes format 2.2 or 4.1 ASCII: one volume entity, node tags 1..n, element type 4.
void writeGmsh(const std::filesystem::path& path, const core::TetMesh& mesh,
               GmshVersion version = GmshVersion::V4);

}  // namespace tfd::io
