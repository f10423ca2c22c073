// A scripted editing session through the editor's public API (offscreen): from an empty canvas
// it builds the default example node by node (one link dragged port to port on the canvas, the
// rest connected through the document), saves it, and checks that the saved file is the
// example's canonical text and that `tfd cook` of it writes the same files as the example.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "graph/graph_file.h"
#include "nodes/register_all.h"
#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"
#include "ui/canvas/canvas_scene.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/window/main_window.h"

namespace tfd::ui {
namespace {

namespace fs = std::filesystem;
using graph::Vec3Param;

std::string bytesOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The session: what a user does with the mouse and the parameter panel, in API calls.
void buildDefaultExample(MainWindow& w) {
  ASSERT_TRUE(w.newFile());
  GraphDocument& d = w.document();
  ASSERT_EQ(d.addNode("TetMesh", {0, 0}, "ball"), "ball");
  ASSERT_TRUE(d.setParam("ball", "target_tets", std::int64_t{60000}));
  struct Point {
    const char* name;
    double y;
    Vec3Param position;
    const char* type;
    const char* pattern;
    Vec3Param rotation;
  };
  const Point points[] = {
      {"linear_wedge", 120, {-0.4, 0, 0}, "linear", "wedge", {0, 0, 0}},
      {"planar_trisector", 240, {0.4, 0, 0}, "planar", "trisector", {90, 0, 0}},
      {"linear_trisector", 360, {0, 0.4, 0.2}, "linear", "trisector", {0, 90, 0}},
      {"planar_wedge", 480, {0, -0.4, -0.2}, "planar", "wedge", {0, 0, 0}}};
  for (const Point& p : points) {
    ASSERT_EQ(d.addNode("PointConstraint", {0, p.y}, p.name), p.name);
    ASSERT_TRUE(d.setParam(p.name, "kind", std::string("degenerate")));
    ASSERT_TRUE(d.setParam(p.name, "position", p.position));
    ASSERT_TRUE(d.setParam(p.name, "type", std::string(p.type)));
    ASSERT_TRUE(d.setParam(p.name, "pattern", std::string(p.pattern)));
    ASSERT_TRUE(d.setParam(p.name, "rotation", p.rotation));
  }
  ASSERT_EQ(d.addNode("PointConstraint", {0, 600}, "stretch"), "stretch");
  ASSERT_TRUE(d.setParam("stretch", "position", Vec3Param{0, 0, 0.6}));
  ASSERT_TRUE(d.setParam("stretch", "eigenvalues", std::vector<double>{1, 0, -1}));
  ASSERT_TRUE(d.setParam("stretch", "rotation", Vec3Param{0, 0, 45}));
  ASSERT_EQ(d.addNode("MergeConstraints", {260, 300}, "design"), "design");
  ASSERT_EQ(d.addNode("Propagate", {500, 150}, "field"), "field");
  ASSERT_EQ(d.addNode("ExtractDegenerateCurves", {740, 300}, "topology"), "topology");
  ASSERT_TRUE(d.setParam("topology", "boundary_curves", std::string("drop")));
  for (auto [name, y, path] : {std::tuple{"curves_json", 360, "default_curves.json"},
                               std::tuple{"curves_vtp", 440, "default_curves.vtp"}}) {
    ASSERT_EQ(d.addNode("ExportCurves", {980, double(y)}, name), name);
    ASSERT_TRUE(d.setParam(name, "path", std::string(path)));
  }
  ASSERT_EQ(d.addNode("ExportVTU", {980, 0}, "vtu"), "vtu");
  ASSERT_TRUE(d.setParam("vtu", "path", std::string("default.vtu")));
  ASSERT_EQ(d.addNode("ExportVDB", {980, 120}, "vdb"), "vdb");
  ASSERT_TRUE(d.setParam("vdb", "path", std::string("default.vdb")));
  ASSERT_TRUE(d.setParam("vdb", "voxel_size", 0.02));
  ASSERT_TRUE(d.setParam("vdb", "quantities",
                         std::vector<std::string>{"tensor", "eigenvalues", "eigenvectors"}));
  ASSERT_EQ(d.addNode("ExportEXR", {980, 240}, "exr"), "exr");
  ASSERT_TRUE(d.setParam("exr", "path", std::string("default_slices/default.%04d.exr")));
  ASSERT_TRUE(d.setParam("exr", "voxel_size", 0.04));

  // The first link is dragged on the canvas from an output port to an input port.
  CanvasScene& canvas = *w.canvas();
  NodeItem* from = canvas.nodeItem("linear_wedge");
  NodeItem* to = canvas.nodeItem("design");
  ASSERT_TRUE(from && to);
  const PortRef out{true, from->decl().outputIndex("constraints")};
  const PortRef in{false, to->decl().inputIndex("constraints")};
  ASSERT_TRUE(canvas.beginLinkDrag("linear_wedge", out));
  canvas.moveLinkDrag(to->portScenePos(in) + QPointF(-30, 5));
  ASSERT_TRUE(canvas.endLinkDrag(to->portScenePos(in)));
  for (auto [a, b] : {std::pair{"planar_trisector.constraints", "design.constraints"},
                      {"linear_trisector.constraints", "design.constraints"},
                      {"planar_wedge.constraints", "design.constraints"},
                      {"stretch.constraints", "design.constraints"},
                      {"ball.mesh", "field.mesh"},
                      {"design.constraints", "field.constraints"},
                      {"field.field", "topology.field"},
                      {"design.constraints", "topology.constraints"},
                      {"field.field", "vtu.field"},
                      {"topology.curves", "vtu.curves"},
                      {"field.field", "vdb.field"},
                      {"field.field", "exr.field"},
                      {"topology.curves", "curves_json.curves"},
                      {"topology.curves", "curves_vtp.curves"}})
    ASSERT_TRUE(d.connect(graph::Endpoint::parse(a), graph::Endpoint::parse(b))) << d.lastError();
}

TEST(ScriptedSession, BuildsTheDefaultExampleAndCooksTheSameFiles) {
  graph::NodeRegistry registry;
  nodes::registerAll(registry);
  test::TempDir dir("scripted-session");
  const fs::path example = fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json";
  const fs::path built = dir.path() / "built.tfd.json";
  {
    MainWindow w(registry);
    w.cook().setAutoCook(false);
    w.prompts.saveChanges = [](const QString&) { return Prompts::Answer::Discard; };
    w.prompts.error = [](const QString& e) { ADD_FAILURE() << e.toStdString(); };
    buildDefaultExample(w);
    if (::testing::Test::HasFatalFailure()) return;
    ASSERT_TRUE(w.saveTo(built));
    EXPECT_FALSE(w.isWindowModified());
  }
  const graph::Graph reference = graph::loadGraphFile(example, registry);
  EXPECT_EQ(graph::readTextFile(built), graph::graphToText(reference))
      << "the saved file is the example's canonical text";

  if (!test::cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  // Smaller sizes keep the test quick; both graphs get the same overrides.
  const std::string sets =
      " --set ball.target_tets=3000 --set vdb.voxel_size=0.08 --set exr.voxel_size=0.08 -q";
  for (auto [graph, out] : {std::pair{example, "from_example"}, {built, "from_editor"}}) {
    const auto r = test::runCli("cook " + test::shellQuote(graph.string()) + sets + " --out " +
                                test::shellQuote((dir.path() / out).string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  std::vector<fs::path> files;
  // The CLI's cook manifest (tfd-cook.json) is not an output of the graph; the editor writes none.
  for (const auto& e : fs::recursive_directory_iterator(dir.path() / "from_example"))
    if (e.is_regular_file() && e.path().filename() != "tfd-cook.json")
      files.push_back(fs::relative(e.path(), dir.path() / "from_example"));
  std::size_t editorFiles = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir.path() / "from_editor"))
    editorFiles += e.is_regular_file() && e.path().filename() != "tfd-cook.json";
  EXPECT_GE(files.size(), 6u);
  EXPECT_EQ(editorFiles, files.size());
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    std::string a = bytesOf(dir.path() / "from_example" / f);
    std::string b = bytesOf(dir.path() / "from_editor" / f);
    ASSERT_GT(a.size(), 64u);
    if (f.extension() == ".vdb") {  // OpenVDB's random file UUID (see cook_nodes_test.cpp)
      a.replace(21, 36, 36, '-');
      b.replace(21, 36, 36, '-');
    }
    EXPECT_TRUE(a == b);
  }
}

}  // namespace
}  // namespace tfd::ui
