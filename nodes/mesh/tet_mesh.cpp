// TetMesh: the volume every field lives on, from a mesh file or a procedural solid
// (paper §4 works on TetGen meshes).
#include <iomanip>
#include <sstream>

#include "core/surface/primitives.h"
#include "io/mesh_file.h"
#include "io/tetgen/surface_meshing.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::PrimitiveShape> kPrimitives{
    {"sphere", core::PrimitiveShape::Sphere},
    {"box", core::PrimitiveShape::Box},
    {"torus", core::PrimitiveShape::Torus},
    {"double_torus", core::PrimitiveShape::DoubleTorus}};

const graph::Choices<io::BoundaryMode> kBoundaryModes{{"auto", io::BoundaryMode::Auto},
                                                      {"keep", io::BoundaryMode::Keep},
                                                      {"refine", io::BoundaryMode::Refine}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "A tetrahedral mesh: read from `file` (a tet mesh is used as is; a closed surface is "
       "tetrahedralised by TetGen after welding vertices at one position or within "
       "`weld_tolerance`, removing repeated triangles and reversing those wound against their "
       "neighbours), or, when "
       "`file` is empty, a procedural solid tetrahedralised by TetGen.")
      .category("Mesh");
  d.output<core::TetMesh>("mesh").doc("Positively oriented tets with their topology.");
  d.param<std::string>("file")
      .byDefault("")
      .inputFile("*.off *.obj *.ply *.stl *.node *.ele *.msh *.vtu")
      .doc(
          "Surface mesh (.off .obj .ply .stl) or tet mesh (.node/.ele .msh .vtu); empty: "
          "use `primitive`.");
  d.param<std::string>("primitive")
      .choices(kPrimitives)
      .doc("Procedural solid centred at the origin (tori lie in the xy plane).");
  d.param<double>("radius").byDefault(1).min(1e-9).doc("sphere: radius.");
  d.param<graph::Vec3Param>("size").byDefault({2, 2, 2}).min(1e-9).doc("box: edge lengths.");
  d.param<double>("major_radius")
      .byDefault(1)
      .min(1e-9)
      .doc("torus, double_torus: ring radius (centre to tube centre).");
  d.param<double>("minor_radius")
      .byDefault(0.4)
      .min(1e-9)
      .doc("torus, double_torus: tube radius, below major_radius.");
  d.param<int>("target_tets")
      .byDefault(20000)
      .min(10)
      .max(10000000)
      .doc(
          "Wanted number of tets (TetGen; within about 25 % for primitives). Ignored for tet "
          "mesh files. The maximum, 10 million, takes TetGen a few minutes and about 4 GB; a "
          "request whose estimated memory exceeds what is available (or --max-memory) is "
          "refused before meshing.");
  d.param<double>("quality").byDefault(1.414).min(0).max(10).doc(
      "TetGen radius-edge ratio bound; 0 switches quality refinement off, otherwise it "
      "must be above 1.1.");
  d.param<double>("time_limit")
      .byDefault(0)
      .min(0)
      .max(86400)
      .doc(
          "Seconds TetGen may run before it is stopped and the node fails; 0: automatic, "
          "30 s + 40 s per million target tets. (Some surfaces, e.g. with one vertex far "
          "away, keep TetGen's refinement from ending.)");
  d.param<double>("weld_tolerance")
      .byDefault(io::kDefaultWeldTolerance)
      .min(0)
      .max(0.5)
      .doc(
          "Surface files: vertices closer than this fraction of the median edge length are "
          "welded into the first of them (seams that exporters write a rounding error apart); "
          "0: only vertices at exactly one position.");
  d.param<int>("fill_holes")
      .byDefault(0)
      .min(0)
      .max(1000000)
      .doc(
          "Surface files: holes (loops of open edges, e.g. where a scanner saw nothing) of at "
          "most this many edges are closed with a fan of triangles around a new vertex; 0: an "
          "open surface is an error, which says how many holes it has and how long they are.");
  d.param<std::string>("boundary")
      .choices(kBoundaryModes)
      .doc(
          "keep: the surface triangles are the mesh boundary (TetGen -Y; the tet count then "
          "follows the surface's resolution); refine: TetGen may split them for quality and "
          "size; auto: keep for primitives and for surfaces already as fine as target_tets "
          "needs, refine coarser ones (e.g. CAD exports).");
}

io::SurfaceMeshingRequest meshingRequest(const graph::CookContext& c, bool procedural,
                                         std::string source) {
  io::SurfaceMeshingRequest r;
  r.targetTets = c.param<int>("target_tets");
  r.quality = c.param<double>("quality");
  if (r.quality != 0 && r.quality <= 1.1)
    throw c.paramError("quality", "TetGen needs a radius-edge bound above 1.1 (or 0 for none)");
  r.boundary = c.param("boundary", kBoundaryModes);
  r.timeLimit = c.param<double>("time_limit");
  r.weldTolerance = c.param<double>("weld_tolerance");
  r.fillHoles = c.param<int>("fill_holes");
  r.procedural = procedural;
  r.source = std::move(source);
  return r;
}

core::PrimitiveSpec primitiveSpec(const graph::CookContext& c) {
  core::PrimitiveSpec spec;
  spec.shape = c.param("primitive", kPrimitives);
  spec.radius = c.param<double>("radius");
  spec.size = vec3Param(c, "size");
  spec.majorRadius = c.param<double>("major_radius");
  spec.minorRadius = c.param<double>("minor_radius");
  if (spec.shape == core::PrimitiveShape::Torus || spec.shape == core::PrimitiveShape::DoubleTorus)
    if (spec.minorRadius >= spec.majorRadius)
      throw c.paramError("minor_radius", "the tube radius must be below major_radius");
  core::validatePrimitive(spec);
  return spec;
}

std::string numberText(double x) {
  std::ostringstream s;
  s << std::setprecision(3) << x;
  return s.str();
}

std::string describe(const core::TetMesh& mesh) {
  std::ostringstream s;
  s << mesh.vertexCount() << " vertices, " << mesh.tetCount() << " tets, "
    << mesh.boundaryFaces().size() << " boundary faces, mean edge " << mesh.meanEdgeLength()
    << ", volume " << mesh.totalVolume();
  return s.str();
}

void cook(graph::CookContext& c) {
  const std::filesystem::path file = c.path("file");
  const core::Progress progress = progressOf(c);
  std::shared_ptr<const core::TetMesh> mesh;
  if (file.empty()) {
    const core::PrimitiveSpec spec = primitiveSpec(c);
    const double target = c.param<int>("target_tets");
    progress.report(0, "surface");
    const core::SurfaceMesh surface = core::makePrimitiveForTets(spec, target);
    progress.report(0.1, "tetgen");
    mesh = io::meshSurface(surface, meshingRequest(c, true, c.param<std::string>("primitive")),
                           nullptr, progress);
  } else if (io::isTetMeshFile(file)) {
    mesh = io::readTetMesh(file);
    c.info("tet mesh read as is: target_tets, quality and boundary do not apply");
  } else {
    progress.report(0.1, "tetgen");
    io::SurfaceMeshingReport report;
    mesh = io::meshSurface(io::readSurfaceMesh(file),
                           meshingRequest(c, false, "file '" + file.string() + "'"), &report,
                           progress);
    if (report.weldedVertices > 0)
      c.info("welded " + std::to_string(report.weldedVertices) +
             (report.weldDistance > 0 ? " vertices repeated at the same position or within " +
                                            numberText(report.weldDistance) + " of another"
                                      : std::string(" vertices repeated at the same position")) +
             (report.droppedTriangles > 0
                  ? ", dropped " + std::to_string(report.droppedTriangles) + " degenerate triangles"
                  : ""));
    if (report.repeatedTriangles > 0)
      c.info("removed " + std::to_string(report.repeatedTriangles) +
             " repeated triangles (copies of a face, or faces shared by two solids)");
    if (report.filledHoles > 0)
      c.info("closed " + std::to_string(report.filledHoles) + " hole" +
             (report.filledHoles == 1 ? "" : "s") + " with " +
             std::to_string(report.holeTriangles) + " triangles");
    if (report.flippedTriangles > 0)
      c.info("reversed " + std::to_string(report.flippedTriangles) +
             " triangles to agree in orientation with their neighbours");
    if (!report.boundaryKept)
      c.info("surface coarser than target_tets needs: TetGen refines the boundary too");
  }
  c.info(describe(*mesh));
  c.setOutput("mesh", std::move(mesh));
}

}  // namespace

void registerTetMesh(graph::NodeRegistry& r) { r.add("TetMesh", 1, declare, cook); }

}  // namespace tfd::nodes
