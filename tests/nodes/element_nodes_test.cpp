// ElementSynthesis and ExportMesh through the real graph: a box with an analytic two-region
// field gives sticks and leaves; the mesh written to .obj and .ply reads back exactly (tfd's
// strict readers), the points .ply holds one vertex per element with orient and pscale; an
// extension the exporter cannot write, or a wrong wiring, fails naming the parameter or ports.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "io/file_bytes.h"
#include "io/mesh_file.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

std::string graphText(const std::string& exporters, const std::string& links) {
  return R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "box": {"type": "TetMesh", "typeVersion": 1,
            "params": {"primitive": "box", "target_tets": 3000}},
    "expr": {"type": "FieldExpression", "typeVersion": 1, "params": {
             "xx": "2*x", "yy": "-x+0.3", "zz": "-x-0.3", "xy": "0.4*y+0.1", "yz": "0.3*z",
             "xz": "0.2+0.2*x"}},
    "elements": {"type": "ElementSynthesis", "typeVersion": 1, "params": {"size": 0.3}})" +
         exporters + R"(},
    "links": [{"from": "box.mesh", "to": "expr.mesh"},
              {"from": "expr.field", "to": "elements.field"})" +
         links + "]}";
}

std::string errorsOf(const graph::NodeReport* r) {
  std::string out;
  for (const graph::NodeMessage& m : r->messages)
    if (m.severity == graph::Severity::Error) out += m.text + "\n";
  return out;
}

TEST(ElementNodes, ExportMeshIsASideEffectNodeAndElementSynthesisIsNot) {
  EXPECT_TRUE(test::builtinNodes().get("ExportMesh").decl().hasSideEffects());
  EXPECT_FALSE(test::builtinNodes().get("ElementSynthesis").decl().hasSideEffects());
}

TEST(ElementNodes, SticksAndLeavesExportedAsMeshAndPoints) {
  test::TempDir dir("element-nodes");
  const std::string text = graphText(
      R"(, "obj": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "e.obj"}},
         "ply": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "e.ply"}},
         "pts": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "p.ply"}})",
      R"(, {"from": "elements.mesh", "to": "obj.mesh"},
         {"from": "elements.mesh", "to": "ply.mesh"},
         {"from": "elements.points", "to": "pts.points"})");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r =
      ev.cook(graph::parseGraph(text, test::builtinNodes(), "elements"), options);
  ASSERT_TRUE(r.ok()) << errorsOf(r.report("obj")) << errorsOf(r.report("elements"));
  const auto mesh = r.output<core::SurfaceMesh>("elements", "mesh");
  const auto points = r.output<core::InstancePoints>("elements", "points");
  int lines = 0, boxes = 0;
  for (const auto& p : points->points) (p.kind == core::ElementKind::Line ? lines : boxes)++;
  EXPECT_GT(lines, 10);
  EXPECT_GT(boxes, 10);
  for (const char* name : {"e.obj", "e.ply"}) {
    SCOPED_TRACE(name);
    const core::SurfaceMesh back = io::readSurfaceMesh(dir.path() / name);
    EXPECT_EQ(back.triangles, mesh->triangles);
    EXPECT_EQ(back.positions, mesh->positions) << "exact coordinates";
  }
  const std::string ply = io::readFileBytes(dir.path() / "p.ply");
  EXPECT_NE(ply.find("element vertex " + std::to_string(points->points.size()) + "\n"),
            std::string::npos);
  for (const char* property :
       {"property float orient_x\n", "property float orient_w\n", "property float pscale\n"})
    EXPECT_NE(ply.find(property), std::string::npos) << property;
  EXPECT_EQ(r.writtenFiles().size(), 3u);
}

TEST(ElementNodes, ExportMeshRefusesWhatItCannotWrite) {
  test::TempDir dir("element-nodes-bad");
  const std::string text = graphText(
      R"(, "stl": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "e.stl"}},
         "pobj": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "p.obj"}},
         "both": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "b.ply"}},
         "none": {"type": "ExportMesh", "typeVersion": 1, "params": {"path": "n.ply"}})",
      R"(, {"from": "elements.mesh", "to": "stl.mesh"},
         {"from": "elements.points", "to": "pobj.points"},
         {"from": "elements.mesh", "to": "both.mesh"},
         {"from": "elements.points", "to": "both.points"})");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r =
      ev.cook(graph::parseGraph(text, test::builtinNodes(), "bad"), options);
  const std::string stl = errorsOf(r.report("stl"));
  EXPECT_NE(stl.find("parameter 'path'"), std::string::npos) << stl;
  EXPECT_NE(stl.find(".obj or .ply"), std::string::npos) << stl;
  const std::string pobj = errorsOf(r.report("pobj"));
  EXPECT_NE(pobj.find("parameter 'path'"), std::string::npos) << pobj;
  EXPECT_NE(pobj.find(".ply"), std::string::npos) << pobj;
  EXPECT_NE(errorsOf(r.report("both")).find("not both"), std::string::npos);
  EXPECT_NE(errorsOf(r.report("none")).find("connect 'mesh' or 'points'"), std::string::npos);
  EXPECT_TRUE(dir.entries().empty()) << "nothing written";
}

}  // namespace
}  // namespace tfd::nodes
