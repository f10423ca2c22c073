#pragma once
// VTK XML UnstructuredGrid (.vtu) tet meshes. Writing .vtu is io/vtk/vtu_writer.h; this reader
// reads what it writes. Every tet-mesh reader follows the conventions of io/tet_mesh_build.h.
#include <filesystem>
#include <memory>

#include "core/tet_mesh.h"

namespace tfd::io {

/// VTK XML UnstructuredGrid (.vtu): ascii, inline base64 ("binary") and appended (raw or
/// base64) data arrays; UInt32 or UInt64 headers; little or big endian; uncompressed or
/// zlib-compressed (vtkZLibDataCompressor, ParaView's default). Several pieces are
/// concatenated. Point data and cell data are ignored.
std::shared_ptr<const core::TetMesh> readVtu(const std::filesystem::path& path);

}  // namespace tfd::io
