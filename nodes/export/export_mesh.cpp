// ExportMesh: a triangle mesh to .obj or .ply, or instance points to .ply (Houdini's orient
// and pscale attribute names).
#include "io/mesh/point_writers.h"
#include "io/mesh/surface_writers.h"

#include "graph/node_registry.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes a triangle mesh (ElementSynthesis, Streamtubes) to .obj or binary .ply, or "
       "instance points to .ply: one vertex per instance with x y z, orient_x orient_y "
       "orient_z orient_w (Houdini's orient quaternion), pscale, scale_x scale_y scale_z and "
       "kind (0 line, 1 box); see docs/outputs.md. Connect exactly one of the two inputs.")
      .category("Export")
      .sideEffect();
  d.input<core::SurfaceMesh>("mesh").optional().doc("Triangles to .obj or .ply.");
  d.input<core::InstancePoints>("points").optional().doc("Instance points to .ply.");
  d.param<std::string>("path")
      .byDefault("mesh.obj")
      .outputFile("*.obj *.ply")
      .doc("Output file: .obj or .ply for a mesh, .ply for points.");
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

void cook(graph::CookContext& c) {
  const bool hasMesh = c.hasInput("mesh"), hasPoints = c.hasInput("points");
  if (hasMesh == hasPoints)
    throw graph::NodeError(hasMesh ? "connect either 'mesh' or 'points', not both"
                                   : "connect 'mesh' or 'points'");
  const std::filesystem::path path = c.path("path");
  const std::string ext = lowerExtension(path);
  if (hasMesh) {
    const auto mesh = c.input<core::SurfaceMesh>("mesh");
    if (ext == ".obj") {
      io::writeObj(path, *mesh);
    } else if (ext == ".ply") {
      io::writePly(path, *mesh);
    } else {
      throw c.paramError(
          "path", "cannot write a mesh to '" + path.filename().string() + "': use .obj or .ply");
    }
    c.wroteFile(path);
    c.info("wrote " + std::to_string(mesh->triangles.size()) + " triangles to " + path.string());
    return;
  }
  if (ext != ".ply")
    throw c.paramError("path", "cannot write points to '" + path.filename().string() +
                                   "': points go to .ply (orient and pscale attributes)");
  const auto points = c.input<core::InstancePoints>("points");
  io::writeInstancePointsPly(path, *points);
  c.wroteFile(path);
  c.info("wrote " + std::to_string(points->points.size()) + " instance points to " + path.string());
}

}  // namespace

void registerExportMesh(graph::NodeRegistry& r) { r.add("ExportMesh", 1, declare, cook); }

}  // namespace tfd::nodes
