#pragma once
// Mesh files by extension: one entry point for nodes, the CLI (`tfd info`) and the editor.
//   surface meshes: .off .obj .ply .stl        (io/surface_readers.h, io/surface_writers.h)
//   tet meshes:     .node .ele .msh .vtu       (io/tet_mesh_io.h, io/vtu_field_writer.h)
// Extensions are matched case-insensitively.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

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

/// A summary of a mesh file, as label/value rows in display order, e.g.
/// {"format", "Gmsh .msh 4.1 (tet mesh)"}, {"vertices", "1234"}, {"tets", "5678"},
/// {"volume", "4.18"}, {"boundary", "closed, Euler characteristic 2 (genus 0)"}, ...
/// The file is read completely (and validated); throws like the readers.
std::vector<std::pair<std::string, std::string>> describeMeshFile(
    const std::filesystem::path& path);

/// The rows above as aligned "label: value" lines.
std::string formatDescription(const std::vector<std::pair<std::string, std::string>>& rows);

}  // namespace tfd::io
