#include "io/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/surface/surface_check.h"
#include "io/file_bytes.h"
#include "io/surface_readers.h"
#include "io/surface_writers.h"
#include "io/tet_mesh_io.h"
#include "io/vtu_field_writer.h"

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

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string vec(const core::Vec3& v) {
  return "(" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + ")";
}

std::string eulerText(long euler, bool connected) {
  std::string s = "Euler characteristic " + std::to_string(euler);
  if (connected && euler % 2 == 0 && euler <= 2) {
    s += " (genus " + std::to_string((2 - euler) / 2) + ")";
  }
  return s;
}

/// Number of connected components of a surface (by shared vertices).
int components(const core::SurfaceMesh& s) {
  std::vector<int> parent(s.positions.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<char> used(s.positions.size(), 0);
  for (const auto& t : s.triangles) {
    for (int v : t) used[v] = 1;
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  int count = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) count += used[i] && find(int(i)) == int(i);
  return count;
}

/// Format details from the first bytes: PLY encoding, STL ASCII/binary, .msh version,
/// VTU encoding.
std::string formatName(const fs::path& path) {
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

std::vector<std::pair<std::string, std::string>> describeMeshFile(const fs::path& path) {
  std::vector<std::pair<std::string, std::string>> rows;
  if (isSurfaceMeshFile(path)) {
    const core::SurfaceMesh s = readSurfaceMesh(path);
    rows.emplace_back("format", formatName(path) + " (surface mesh)");
    rows.emplace_back("vertices", std::to_string(s.positions.size()));
    rows.emplace_back("triangles", std::to_string(s.triangles.size()));
    core::Vec3 lo = core::Vec3::Constant(INFINITY), hi = core::Vec3::Constant(-INFINITY);
    for (const auto& p : s.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    rows.emplace_back("bounds", vec(lo) + " to " + vec(hi));
    rows.emplace_back("mean edge length", number(core::meanEdgeLength(s)));
    rows.emplace_back("area", number(core::surfaceArea(s)));
    const auto problems = core::closedSurfaceProblems(s, 1);
    const int parts = components(s);
    rows.emplace_back("components", std::to_string(parts));
    if (problems.empty()) {
      rows.emplace_back("closed", "yes, manifold, consistently oriented; " +
                                      eulerText(core::eulerCharacteristic(s), parts == 1));
      const double v = core::enclosedVolume(s);
      rows.emplace_back("volume", number(std::abs(v)) + (v < 0 ? " (triangles face inward)" : ""));
    } else {
      rows.emplace_back("closed", "no: " + problems.front());
    }
  } else if (isTetMeshFile(path)) {
    const auto m = readTetMesh(path);
    rows.emplace_back("format", formatName(path) + " (tet mesh)");
    rows.emplace_back("vertices", std::to_string(m->vertexCount()));
    rows.emplace_back("tets", std::to_string(m->tetCount()));
    rows.emplace_back("bounds", vec(m->boundsMin()) + " to " + vec(m->boundsMax()));
    rows.emplace_back("volume", number(m->totalVolume()));
    const auto& vols = m->tetVolumes();
    rows.emplace_back("tet volume", "min " + number(*std::min_element(vols.begin(), vols.end())) +
                                        ", max " +
                                        number(*std::max_element(vols.begin(), vols.end())));
    rows.emplace_back("mean edge length", number(m->meanEdgeLength()));
    core::SurfaceMesh boundary;
    boundary.positions = m->positions();
    for (int f : m->boundaryFaces()) boundary.triangles.push_back(m->orientedBoundaryFace(f));
    const int parts = components(boundary);
    rows.emplace_back("boundary", std::to_string(m->boundaryFaces().size()) + " faces, " +
                                      std::to_string(m->boundaryVertices().size()) + " vertices, " +
                                      std::to_string(parts) + " component" +
                                      (parts == 1 ? "" : "s") + ", " +
                                      eulerText(core::eulerCharacteristic(boundary), parts == 1));
  } else {
    unknownFormat(path, "mesh", ".off, .obj, .ply, .stl, .node, .ele, .msh or .vtu");
  }
  return rows;
}

std::string formatDescription(const std::vector<std::pair<std::string, std::string>>& rows) {
  std::size_t width = 0;
  for (const auto& [label, value] : rows) width = std::max(width, label.size());
  std::string out;
  for (const auto& [label, value] : rows) {
    out += label + ":" + std::string(width - label.size() + 1, ' ') + value + "\n";
  }
  return out;
}

}  // namespace tfd::io
