#pragma once
// Mesh files by extension: one entry point for nodes, the CLI (`tfd info`) and the editor.
//   surface meshes: .off .obj .ply .stl        (io/mesh/surface_readers.h,
//   io/mesh/surface_writers.h) tet meshes:     .node .ele .msh .vtu       (io/tet_mesh_io.h,
//   io/vtk/vtu_writer.h)
// Extensions are matched case-insensitively.
#include <filesystem>
#include <memory>
#include <string>

#include "core/surface/surface_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::io {

bool isSurfaceMeshFile(const std::filesystem::path& path);
bool isTetMeshFile(const std::filesystem::path& path);

/// Reads a surface mesh by extension. Throws core::Error naming the file for an unknown
/// extension (listing the known ones) and for any problem the reader finds.
core::SurfaceMesh readSurfaceMesh(const std::filesystem::path& path);

/// Reads a tet mesh by extension (see isTetMeshFile).
std::shared_ptr<const core::TetMesh> readTetMesh(const std::filesystem::path& path);

/// Writes a surface mesh by extension: .off, .obj, binary little-endian .ply, binary .stl.
void writeSurfaceMesh(const std::filesystem::path& path, const core::SurfaceMesh& mesh);

/// Writes a tet mesh by extension: .node/.ele (both files), .msh (format 4.1 ASCII) or .vtu
/// (raw appended binary).
void writeTetMesh(const std::filesystem::path& path, const core::TetMesh& mesh);

/// The format of a mesh file as its extension and first bytes tell, e.g. "OFF",
/// "PLY (binary_little_endian)", "STL (binary)", "Gmsh .msh 4.1 (ASCII)",
/// "VTK XML .vtu (appended, zlib-compressed)". Reads the file; throws core::Error naming it.
std::string meshFileFormat(const std::filesystem::path& path);

}  // namespace tfd::io
