#include "io/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/mesh/gmsh.h"
#include "io/mesh/surface_readers.h"
#include "io/mesh/surface_writers.h"
#include "io/tetgen/node_ele.h"
#include "io/vtk/vtu_reader.h"
#include "io/vtk/vtu_writer.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;

std::string extensionOf(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

[[noreturn]] void unknownFormat(const fs::path& path, const char* kind, const char* known) {
  const std::string ext = path.extension().string();
  throw core::Error("file '" + path.string() + "': unknown " + kind + " format '" +
                    (ext.empty() ? std::string("(no extension)") : ext) + "' (expected " + known +
                    ")");
}

constexpr const char* kSurfaceExtensions = ".off, .obj, .ply or .stl";
constexpr const char* kTetExtensions = ".node, .ele, .msh or .vtu";

}  // namespace

bool isSurfaceMeshFile(const fs::path& path) {
  const std::string ext = extensionOf(path);
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

bool isTetMeshFile(const fs::path& path) {
  const std::string ext = extensionOf(path);
  return ext == ".node" || ext == ".ele" || ext == ".msh" || ext == ".vtu";
}

core::SurfaceMesh readSurfaceMesh(const fs::path& path) {
  const std::string ext = extensionOf(path);
  if (ext == ".off") return readOff(path);
  if (ext == ".obj") return readObj(path);
  if (ext == ".ply") return readPly(path);
  if (ext == ".stl") return readStl(path);
  unknownFormat(path, "surface mesh", kSurfaceExtensions);
}

std::shared_ptr<const core::TetMesh> readTetMesh(const fs::path& path) {
  const std::string ext = extensionOf(path);
  if (ext == ".node" || ext == ".ele") return readTetgen(path);
  if (ext == ".msh") return readGmsh(path);
  if (ext == ".vtu") return readVtu(path);
  unknownFormat(path, "tet mesh", kTetExtensions);
}

void writeSurfaceMesh(const fs::path& path, const core::SurfaceMesh& mesh) {
  const std::string ext = extensionOf(path);
  if (ext == ".off") return writeOff(path, mesh);
  if (ext == ".obj") return writeObj(path, mesh);
  if (ext == ".ply") return writePly(path, mesh, PlyEncoding::BinaryLittleEndian);
  if (ext == ".stl") return writeStl(path, mesh, true);
  unknownFormat(path, "surface mesh", kSurfaceExtensions);
}

void writeTetMesh(const fs::path& path, const core::TetMesh& mesh) {
  const std::string ext = extensionOf(path);
  if (ext == ".node" || ext == ".ele") return writeTetgen(path, mesh);
  if (ext == ".msh") return writeGmsh(path, mesh, GmshVersion::V4);
  if (ext == ".vtu") return writeMeshVtu(path, mesh, VtuMeshOptions{});
  unknownFormat(path, "tet mesh", kTetExtensions);
}

std::string meshFileFormat(const fs::path& path) {
  const std::string ext = extensionOf(path);
  std::string head;
  {
    const std::string bytes = readFileBytes(path);
    head = bytes.substr(0, 4096);
    if (ext == ".stl") {
      const bool binary =
          bytes.size() >= 84 &&
          bytes.size() ==
              84 + 50 * std::uint64_t((unsigned char)bytes[80] | (unsigned char)bytes[81] << 8 |
                                      (unsigned char)bytes[82] << 16 |
                                      std::uint64_t((unsigned char)bytes[83]) << 24);
      return binary ? "STL (binary)" : "STL (ASCII)";
    }
  }
  if (ext == ".off") return "OFF";
  if (ext == ".obj") return "Wavefront OBJ";
  if (ext == ".ply") {
    for (const char* f : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      if (head.find(std::string("format ") + f) != std::string::npos)
        return std::string("PLY (") + f + ")";
    }
    return "PLY";
  }
  if (ext == ".node" || ext == ".ele") return "TetGen .node/.ele";
  if (ext == ".msh") {
    const std::size_t at = head.find("$MeshFormat");
    if (at != std::string::npos) {
      std::istringstream s(head.substr(at + 11));
      std::string version;
      s >> version;
      return "Gmsh .msh " + version + " (ASCII)";
    }
    return "Gmsh .msh";
  }
  if (ext == ".vtu") {
    std::string detail;
    if (head.find("vtkZLibDataCompressor") != std::string::npos) detail = ", zlib-compressed";
    if (head.find("format=\"appended\"") != std::string::npos)
      return "VTK XML .vtu (appended" + detail + ")";
    if (head.find("format=\"binary\"") != std::string::npos)
      return "VTK XML .vtu (base64" + detail + ")";
    return "VTK XML .vtu (ascii)";
  }
  return ext;
}

}  // namespace tfd::io
