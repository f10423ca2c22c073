#pragma once
// Tetrahedral mesh files: TetGen .node/.ele, Gmsh .msh (v2 and v4 ASCII) and VTK .vtu.
// Writing .vtu is io::writeMeshVtu (io/vtu_field_writer.h); this reader reads what it writes.
//
// All readers return a validated, positively oriented core::TetMesh:
// - only tetrahedra are read; lower-dimensional elements (points, lines, triangles, quads) are
//   ignored, other volume elements (hexahedra, prisms, pyramids) are an error; second- and
//   higher-order tets keep their four corners;
// - vertices no tet uses are dropped (the others keep their file order);
// - a mesh whose tets are all negatively oriented is flipped silently; a mix is an error from
//   core::TetMesh naming the tet ("file 'x.msh': invalid tet mesh (...): tet 12 is inverted").
// Errors are core::Error naming the file and, for text, the line, what was expected and what
// was found, as for the surface readers.
#include <filesystem>
#include <memory>

#include "core/tet_mesh.h"

namespace tfd::io {

/// TetGen files. `path` is the .node file, the .ele file or their common base name; both are
/// read. Numbering starts at 0 or 1 as the first point of the .node file says; point and tet
/// attributes and boundary markers are ignored.
std::shared_ptr<const core::TetMesh> readTetgen(const std::filesystem::path& path);
/// Writes base.node and base.ele (1-based, no attributes) for `path` = base, base.node or
/// base.ele; each file is written atomically.
void writeTetgen(const std::filesystem::path& path, const core::TetMesh& mesh);

/// Gmsh ASCII .msh, format 2.x or 4.x ($MeshFormat says which). Node tags may be sparse and
/// in any order (they are mapped); 4.x entity blocks and parametric coordinates are handled;
/// $Entities, $PhysicalNames and other sections are skipped. Binary .msh is refused.
std::shared_ptr<const core::TetMesh> readGmsh(const std::filesystem::path& path);

enum class GmshVersion { V2, V4 };
/// Writes format 2.2 or 4.1 ASCII: one volume entity, node tags 1..n, element type 4.
void writeGmsh(const std::filesystem::path& path, const core::TetMesh& mesh,
               GmshVersion version = GmshVersion::V4);

/// VTK XML UnstructuredGrid (.vtu): ascii, inline base64 ("binary") and appended (raw or
/// base64) data arrays; UInt32 or UInt64 headers; little or big endian; uncompressed or
/// zlib-compressed (vtkZLibDataCompressor, ParaView's default). Several pieces are
/// concatenated. Point data and cell data are ignored.
std::shared_ptr<const core::TetMesh> readVtu(const std::filesystem::path& path);

}  // namespace tfd::io
