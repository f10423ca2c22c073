// `tfd info` of a mesh file: counts, bounds, volume and the topology of its surface.
#include "apps/tfd/describe_io_files.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/surface/surface_cavities.h"
#include "core/surface/surface_check.h"
#include "io/mesh_file.h"
#include "io/tetgen/surface_meshing.h"

namespace tfd::cli {
namespace {

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

std::string countText(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// What the TetMesh node, with its default parameters, does to a surface before TetGen: the
/// repairs it makes, then the solid it gets or why it refuses the file.
std::string tetMeshPreparation(core::SurfaceMesh s) {
  io::SurfaceMeshingRequest request;
  io::SurfaceMeshingReport report;
  try {
    io::prepareFileSurface(s, request, report);
  } catch (const core::Error& e) {
    return std::string("refuses it: ") + e.what();
  }
  std::vector<std::string> repairs;
  if (report.weldedVertices > 0)
    repairs.push_back("welds " + countText(report.weldedVertices, "vertex", "vertices") +
                      " within " + number(report.weldDistance));
  if (report.droppedTriangles > 0)
    repairs.push_back("drops " + countText(report.droppedTriangles, "degenerate triangle",
                                           "degenerate triangles"));
  if (report.repeatedTriangles > 0)
    repairs.push_back("removes " + countText(report.repeatedTriangles, "repeated triangle",
                                             "repeated triangles"));
  if (report.flippedTriangles > 0)
    repairs.push_back("reverses " + countText(report.flippedTriangles, "triangle", "triangles"));
  std::string text = repairs.empty() ? "uses it as it is" : "";
  for (std::size_t i = 0; i < repairs.size(); ++i) text += (i ? ", " : "") + repairs[i];
  text += "; solid volume " + number(std::abs(core::enclosedVolume(s)));
  if (const std::size_t voids = core::cavityPoints(s).size(); voids > 0)
    text += " with " + countText(voids, "void", "voids") + " kept empty";
  return text;
}

}  // namespace

Rows describeMeshFile(const std::filesystem::path& path) {
  Rows rows;
  if (io::isSurfaceMeshFile(path)) {
    const core::SurfaceMesh s = io::readSurfaceMesh(path);
    rows.emplace_back("format", io::meshFileFormat(path) + " (surface mesh)");
    rows.emplace_back("vertices", std::to_string(s.positions.size()));
    rows.emplace_back("triangles", std::to_string(s.triangles.size()));
    core::Vec3 lo = core::Vec3::Constant(INFINITY), hi = core::Vec3::Constant(-INFINITY);
    for (const auto& p : s.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    rows.emplace_back("bounds", vec(lo) + " to " + vec(hi));
    rows.emplace_back("mean edge length", number(core::meanEdgeLength(s)));
    rows.emplace_back("area", number(core::surfaceArea(s)));
    const auto problems = core::closedSurfaceProblems(s, 1);
    const int parts = core::connectedComponents(s);
    rows.emplace_back("components", std::to_string(parts));
    if (problems.empty()) {
      rows.emplace_back("closed", "yes, manifold, consistently oriented; " +
                                      eulerText(core::eulerCharacteristic(s), parts == 1));
      const double v = core::enclosedVolume(s);
      rows.emplace_back("volume", number(std::abs(v)) + (v < 0 ? " (triangles face inward)" : ""));
    } else {
      rows.emplace_back("closed", "no: " + problems.front());
    }
    rows.emplace_back("TetMesh node", tetMeshPreparation(s));
  } else if (io::isTetMeshFile(path)) {
    const auto m = io::readTetMesh(path);
    rows.emplace_back("format", io::meshFileFormat(path) + " (tet mesh)");
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
    const int parts = core::connectedComponents(boundary);
    rows.emplace_back("boundary", std::to_string(m->boundaryFaces().size()) + " faces, " +
                                      std::to_string(m->boundaryVertices().size()) + " vertices, " +
                                      std::to_string(parts) + " component" +
                                      (parts == 1 ? "" : "s") + ", " +
                                      eulerText(core::eulerCharacteristic(boundary), parts == 1));
  } else {
    throw core::Error(
        "file '" + path.string() +
        "': not a mesh file (expected .off, .obj, .ply, .stl, .node, .ele, .msh or .vtu)");
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

}  // namespace tfd::cli
