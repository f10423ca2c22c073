// Hyperstreamlines -> Streamtubes and ExportLines as a user wires them: F1's medium lines on a
// TetGen box, tubes around them, the .vtp and .obj files on disk; a separation too small for
// the mesh fails the node with a message naming it.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd::nodes {
namespace {

std::string graphText(const std::string& separation) {
  return R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "box": {"type": "TetMesh", "typeVersion": 1,
            "params": {"primitive": "box", "size": [1, 1, 0.4], "target_tets": 6000}},
    "expr": {"type": "FieldExpression", "typeVersion": 1,
             "params": {"xx": "x-1", "yy": "-x-1", "zz": "2", "xy": "y", "yz": "0", "xz": "0"}},
    "lines": {"type": "Hyperstreamlines", "typeVersion": 1,
              "params": {"direction": "medium", "separation": )" +
         separation + R"(, "min_length": 0.05}},
    "tubes": {"type": "Streamtubes", "typeVersion": 1,
              "params": {"radius": 0.01, "sides": 6, "width_by": "medium"}},
    "vtp": {"type": "ExportLines", "typeVersion": 1, "params": {"path": "noodles.vtp"}},
    "obj": {"type": "ExportLines", "typeVersion": 1, "params": {"path": "noodles.obj"}}},
    "links": [{"from": "box.mesh", "to": "expr.mesh"},
              {"from": "expr.field", "to": "lines.field"},
              {"from": "lines.lines", "to": "tubes.lines"},
              {"from": "lines.lines", "to": "vtp.lines"},
              {"from": "lines.lines", "to": "obj.lines"}]})";
}

TEST(LinesNodes, HyperstreamlinesToTubesAndFiles) {
  test::TempDir dir("lines-nodes");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator evaluator;
  const graph::CookResult r =
      evaluator.cook(graph::parseGraph(graphText("0.08"), test::builtinNodes(), "lines"), options);
  ASSERT_TRUE(r.ok());
  const auto lines = r.output<core::Polylines>("lines", "lines");
  ASSERT_GT(lines->lines.size(), 10u) << lines->summary();
  EXPECT_EQ(lines->family, core::EigenFamily::Medium);
  for (const core::Polyline& l : lines->lines) EXPECT_GE(l.length(), 0.05);
  const auto tubes = r.output<core::SurfaceMesh>("tubes", "mesh");
  EXPECT_EQ(tubes->positions.size(), lines->pointCount() * 6 + 2 * lines->lines.size());
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"noodles.obj", "noodles.vtp"}));
  const test::VtkXmlFile vtp = test::readVtkXmlFile(dir.path() / "noodles.vtp");
  const auto& piece = vtp.root.child("PolyData").child("Piece");
  EXPECT_EQ(piece.attribute("NumberOfPoints"), std::to_string(lines->pointCount()));
  EXPECT_EQ(piece.attribute("NumberOfLines"), std::to_string(lines->lines.size()));
  EXPECT_EQ(vtp.values(vtp.array(piece.child("PointData"), "eigenvalues")).size(),
            3 * lines->pointCount());
  EXPECT_EQ(r.writtenFiles().size(), 2u);
}

TEST(LinesNodes, ASeparationTooSmallForTheMeshFailsTheNodeNamingIt) {
  test::TempDir dir("lines-nodes-bad");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator evaluator;
  const graph::CookResult r = evaluator.cook(
      graph::parseGraph(graphText("0.0001"), test::builtinNodes(), "lines"), options);
  ASSERT_FALSE(r.ok());
  const graph::NodeReport* rep = r.report("lines");
  ASSERT_TRUE(rep);
  ASSERT_FALSE(rep->messages.empty());
  EXPECT_NE(rep->messages[0].text.find("separation"), std::string::npos) << rep->messages[0].text;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace tfd::nodes
