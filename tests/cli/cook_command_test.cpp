// End-to-end tests of `tfd cook` with the real node types: a good graph (files, info lines,
// the topology summary, --profile lines), a failing node, a missing mesh file, --set,
// --strict and identical output for 1 and 2 threads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

bool has(const std::string& text, const std::string& needle) {
  return text.find(needle) != std::string::npos;
}

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ordered_json node(const std::string& type, ordered_json params = ordered_json::object()) {
  return {{"type", type}, {"typeVersion", 1}, {"params", std::move(params)}};
}

/// A small design: ball, two degenerate points, boundary-conforming propagation, extraction,
/// and every exporter.
ordered_json designGraph() {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"ball", node("TetMesh", {{"target_tets", 4000}})},
                {"wedge", node("PointConstraint", {{"kind", "degenerate"},
                                                   {"position", {-0.3, 0.05, 0.02}},
                                                   {"type", "linear"},
                                                   {"pattern", "wedge"}})},
                {"trisector", node("PointConstraint", {{"kind", "degenerate"},
                                                       {"position", {0.3, -0.05, 0.03}},
                                                       {"type", "planar"},
                                                       {"pattern", "trisector"}})},
                {"design", node("MergeConstraints")},
                {"field", node("Propagate")},
                {"topology", node("ExtractDegenerateCurves")},
                {"vtu", node("ExportVTU", {{"path", "field.vtu"}})},
                {"vdb", node("ExportVDB", {{"path", "field.vdb"}, {"voxel_size", 0.1}})},
                {"exr", node("ExportEXR", {{"path", "slices/f.%03d.exr"}, {"voxel_size", 0.2}})},
                {"curves", node("ExportCurves", {{"path", "curves.json"}})}};
  g["links"] = {{{"from", "wedge.constraints"}, {"to", "design.constraints"}},
                {{"from", "trisector.constraints"}, {"to", "design.constraints"}},
                {{"from", "ball.mesh"}, {"to", "field.mesh"}},
                {{"from", "design.constraints"}, {"to", "field.constraints"}},
                {{"from", "field.field"}, {"to", "topology.field"}},
                {{"from", "field.field"}, {"to", "vtu.field"}},
                {{"from", "topology.curves"}, {"to", "vtu.curves"}},
                {{"from", "field.field"}, {"to", "vdb.field"}},
                {{"from", "field.field"}, {"to", "exr.field"}},
                {{"from", "topology.curves"}, {"to", "curves.curves"}}};
  return g;
}

class CookNodes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  }
  fs::path write(const ordered_json& graph, const std::string& name = "g.tfd.json") {
    const fs::path path = dir.path() / name;
    std::ofstream(path) << graph.dump(2);
    return path;
  }
  CliRun cook(const fs::path& graph, const std::string& extra = {}) {
    return runCli("cook " + shellQuote(graph.string()) + " " + extra);
  }
  TempDir dir{"cook-nodes"};
};

TEST_F(CookNodes, GoodGraphWritesEveryFileAndReportsTopologyAndProfile) {
  const fs::path graph = write(designGraph());
  const fs::path out = dir.path() / "out";
  const CliRun r = cook(graph, "--out " + shellQuote(out.string()) + " --profile");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* file : {"field.vtu", "field.vdb", "curves.json", "slices/f.000.exr"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  EXPECT_FALSE(fs::exists(dir.path() / "field.vtu")) << "outputs go to --out";
  EXPECT_TRUE(has(r.out, "info: node \"ball\": ")) << r.out;
  // The topology summary after extraction: curves by type, loops, transition points.
  const std::regex summary(
      R"(info: node "topology": \d+ degenerate curves? \(\d+ linear, \d+ planar)");
  EXPECT_TRUE(std::regex_search(r.out, summary)) << r.out;
  EXPECT_TRUE(has(r.out, "transition point")) << r.out;
  // One profile line per cooked node, exactly "profile <node> <type> <seconds>".
  const std::regex line(R"(^profile (\S+) (\S+) (\d+\.\d+)$)");
  std::istringstream lines(r.out);
  int profiled = 0;
  for (std::string text; std::getline(lines, text);)
    if (text.rfind("profile ", 0) == 0) {
      EXPECT_TRUE(std::regex_match(text, line)) << text;
      ++profiled;
    }
  EXPECT_EQ(profiled, 10);
  EXPECT_TRUE(has(r.out, "profile field Propagate ")) << r.out;
  const auto curves = nlohmann::json::parse(bytesOf(out / "curves.json"));
  EXPECT_EQ(curves["format"], "tfd-degenerate-curves");
  EXPECT_FALSE(curves["curves"].empty());
}

TEST_F(CookNodes, FailingNodeExitsOneNamingItAndTheRestStillCooks) {
  ordered_json g = designGraph();
  g["nodes"]["wedge"]["params"]["position"] = {5, 5, 5};  // outside the ball
  // An unrelated branch on the same mesh must still be written.
  g["nodes"]["expr"] = node("FieldExpression", {{"xx", "x"}, {"yy", "-x"}});
  g["nodes"]["expr_vtu"] = node("ExportVTU", {{"path", "expr.vtu"}});
  g["links"].push_back({{"from", "ball.mesh"}, {"to", "expr.mesh"}});
  g["links"].push_back({{"from", "expr.field"}, {"to", "expr_vtu.field"}});
  const CliRun r = cook(write(g));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(has(r.err, "tfd: node \"field\" (Propagate): ")) << r.err;
  EXPECT_TRUE(has(r.err, "outside")) << r.err;
  EXPECT_TRUE(has(r.err, "1 node failed, 5 not cooked because of that")) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir.path() / "expr.vtu"));
  EXPECT_FALSE(fs::exists(dir.path() / "field.vtu"));
  EXPECT_FALSE(fs::exists(dir.path() / "field.vdb"));
}

TEST_F(CookNodes, MissingMeshFileFailsTheNodeNamingTheFile) {
  ordered_json g = designGraph();
  g["nodes"]["ball"]["params"]["file"] = "no_such_mesh.obj";
  const CliRun r = cook(write(g));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(has(r.err, "tfd: node \"ball\" (TetMesh): ")) << r.err;
  EXPECT_TRUE(has(r.err, (dir.path() / "no_such_mesh.obj").string())) << r.err;
  EXPECT_TRUE(dir.entries() == (std::vector<std::string>{"g.tfd.json", "tfd-cook.json"}))
      << "no output written (but the manifest saying the cook failed)";
}

TEST_F(CookNodes, SetOverridesScalarsStringsAndVectors) {
  const fs::path graph = write(designGraph());
  CliRun r = cook(graph, "--set vtu.path=renamed.vtu --set ball.target_tets=3000 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir.path() / "renamed.vtu"));
  EXPECT_FALSE(fs::exists(dir.path() / "field.vtu"));
  // A vector override moves the element outside the ball: the cook must now fail.
  r = cook(graph, "--set 'wedge.position=[4,0,0]' --quiet");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(has(r.err, "node \"field\" (Propagate)")) << r.err;
  r = cook(graph, "--set ball.primitive=cube");
  EXPECT_EQ(r.exitCode, 2) << "a value outside the choices is a usage error";
  EXPECT_TRUE(has(r.err, "primitive")) << r.err;
}

TEST_F(CookNodes, StrictTurnsWarningsIntoFailure) {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"box", node("TetMesh", {{"primitive", "box"}, {"target_tets", 2000}})},
                {"constant", node("FieldExpression", {{"xx", "1"}, {"yy", "-1"}, {"xy", "0"}})},
                {"topology", node("ExtractDegenerateCurves")},
                {"curves", node("ExportCurves", {{"path", "c.obj"}})}};
  g["links"] = {{{"from", "box.mesh"}, {"to", "constant.mesh"}},
                {{"from", "constant.field"}, {"to", "topology.field"}},
                {{"from", "topology.curves"}, {"to", "curves.curves"}}};
  const fs::path graph = write(g);
  CliRun r = cook(graph);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "tfd: warning: node \"topology\" (ExtractDegenerateCurves): ")) << r.err;
  r = cook(graph, "--strict --quiet");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(has(r.err, "--strict: 1 warning treated as errors")) << r.err;
}

TEST_F(CookNodes, OneAndTwoThreadsWriteIdenticalFiles) {
  const fs::path graph = write(designGraph());
  const fs::path one = dir.path() / "one", two = dir.path() / "two";
  ASSERT_EQ(cook(graph, "--quiet --threads 1 --out " + shellQuote(one.string())).exitCode, 0);
  ASSERT_EQ(cook(graph, "--quiet --threads 2 --out " + shellQuote(two.string())).exitCode, 0);
  for (const char* file : {"field.vtu", "field.vdb", "curves.json", "slices/f.000.exr"}) {
    SCOPED_TRACE(file);
    std::string a = bytesOf(one / file), b = bytesOf(two / file);
    ASSERT_GT(a.size(), 64u);
    if (fs::path(file).extension() == ".vdb") {
      // OpenVDB writes a random 36-character file UUID after the 21-byte header prefix
      // (magic, file version, library version, grid-offsets flag); everything else must match.
      EXPECT_NE(a.substr(21, 36), b.substr(21, 36)) << "the UUID is where we think it is";
      a.replace(21, 36, 36, '-');
      b.replace(21, 36, 36, '-');
    }
    EXPECT_TRUE(a == b);
  }
}

TEST_F(CookNodes, InfoDescribesEveryExportedFile) {
  const fs::path out = dir.path() / "out";
  ordered_json graph = designGraph();
  graph["nodes"]["curves_vtp"] = node("ExportCurves", {{"path", "curves.vtp"}});
  graph["links"].push_back({{"from", "topology.curves"}, {"to", "curves_vtp.curves"}});
  ASSERT_EQ(cook(write(graph), "--quiet --out " + shellQuote(out.string())).exitCode, 0);
  const std::pair<const char*, std::vector<std::string>> expected[] = {
      {"field.vdb", {"format:", "OpenVDB volume", "grid T.xx:", "float", "metadata generator:"}},
      {"slices/f.000.exr", {"OpenEXR image", "T.xx (float)", "tfd.voxelSize:", "0.2"}},
      {"curves.json", {"tfd degenerate curves, version 1", "curves:", "transition points"}},
      {"field.vtu",
       {"tet mesh", "tets:", "Euler characteristic 2", "point arrays:",
        "T (Float64 × 6, active Tensors)", "cell arrays:", "curve_colour (UInt8 × 3)"}},
      {"curves.vtp",
       {"VTK XML PolyData", "lines:", "colour (UInt8 × 3, active Scalars)", "cell arrays:"}}};
  for (const auto& [file, needles] : expected) {
    SCOPED_TRACE(file);
    const CliRun r = runCli("info " + shellQuote((out / file).string()));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& needle : needles) EXPECT_TRUE(has(r.out, needle)) << r.out;
  }
  std::ofstream(dir.path() / "other.json") << R"({"format": "something-else"})";
  const CliRun r = runCli("info " + shellQuote((dir.path() / "other.json").string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "not a tfd-degenerate-curves file")) << r.err;
}

}  // namespace
}  // namespace tfd::test
