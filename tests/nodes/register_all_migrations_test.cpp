// Node typeVersion migrations of the registered types: files written before a parameter was
// renamed or changed kind load with the same meaning and save as the current version; a graph
// file of format version 1 with every registered type at typeVersion 1 loads; and every
// typeVersion of every registered type has a fixture (tests/data/graphs/nodes/, migrations/ or
// an example) that loads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "tests/support/builtin_nodes.h"

namespace tfd::nodes {
namespace {

using Strings = std::vector<std::string>;
const char* kFixture = TFD_TEST_DATA_DIR "/graphs/migrations/exporters_v1.tfd.json";

TEST(NodeMigrations, ExportersOfTypeVersion1KeepTheirMeaning) {
  const graph::Graph g = graph::loadGraphFile(kFixture, test::builtinNodes());
  // ExportVTU 1 -> 2: raw appended data was called "binary".
  EXPECT_EQ(std::get<std::string>(g.param("vtu", "encoding")), "appended");
  EXPECT_EQ(std::get<std::string>(g.param("vtu_ascii", "encoding")), "ascii");
  // ExportVDB 1 -> 2: the comma-separated string becomes a list (blanks and empty items go).
  EXPECT_EQ(std::get<Strings>(g.param("vdb", "quantities")), (Strings{"tensor", "eigenvectors"}));
  // ExportEXR 1 -> 2: `quantity` is renamed `quantities` and becomes a list.
  EXPECT_EQ(std::get<Strings>(g.param("exr", "quantities")), (Strings{"eigenvalues"}));
  EXPECT_EQ(std::get<Strings>(g.param("exr_default", "quantities")), (Strings{"tensor"}));
}

TEST(NodeMigrations, UpgradedFilesSaveAsTheCurrentTypeVersionAndLoadAgain) {
  const graph::Graph g = graph::loadGraphFile(kFixture, test::builtinNodes());
  const graph::Json saved = graph::graphToJson(g);
  for (const char* node : {"vtu", "vdb", "exr"}) {
    EXPECT_EQ(saved["nodes"][node]["typeVersion"], node == std::string("vdb") ? 3 : 2) << node;
    EXPECT_FALSE(saved["nodes"][node]["params"].contains("quantity")) << node;
  }
  EXPECT_EQ(saved["nodes"]["exr"]["params"]["quantities"],
            graph::Json::parse(R"(["eigenvalues"])"));
  const std::string text = graph::graphToText(g);
  const graph::Graph again = graph::parseGraph(text, test::builtinNodes(), "saved");
  EXPECT_EQ(graph::graphToText(again), text);
}

TEST(NodeMigrations, ExportVdbOfTypeVersion2WritesNoDensityGridAsBefore) {
  // ExportVDB 2 -> 3: the `density` grid from a field is new; older files keep the grids they
  // wrote (density "none"), new nodes get the default, closeness to degeneracy.
  const graph::Graph g = graph::loadGraphFile(
      TFD_TEST_DATA_DIR "/graphs/nodes/exporters_v3.tfd.json", test::builtinNodes());
  EXPECT_EQ(std::get<std::string>(g.param("vdb_v2", "density")), "none");
  EXPECT_EQ(std::get<std::string>(g.param("vdb_v3", "density")), "anisotropy");
  const graph::Graph v1 = graph::loadGraphFile(kFixture, test::builtinNodes());
  EXPECT_EQ(std::get<std::string>(v1.param("vdb", "density")), "none");
  const graph::Graph fresh = graph::parseGraph(
      R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
        "v": {"type": "ExportVDB", "typeVersion": 3, "params": {}}}, "links": []})",
      test::builtinNodes(), "new.tfd.json");
  EXPECT_EQ(std::get<std::string>(fresh.param("v", "density")), "degeneracy");
}

TEST(NodeMigrations, PointConstraintsOfTypeVersion1KeepTheirSupport) {
  // PointConstraint 1 -> 2: radius 0 (or none) meant the holding tet only; the new default
  // support is auto (a few mean edge lengths), so old files must say `tet` explicitly.
  const graph::Graph g = graph::loadGraphFile(
      TFD_TEST_DATA_DIR "/graphs/migrations/point_constraint_v1.tfd.json", test::builtinNodes());
  EXPECT_EQ(std::get<std::string>(g.param("in_tet", "support")), "tet");
  EXPECT_EQ(std::get<std::string>(g.param("zero_radius", "support")), "tet");
  EXPECT_EQ(std::get<std::string>(g.param("with_radius", "support")), "radius");
  EXPECT_EQ(std::get<double>(g.param("with_radius", "radius")), 0.25);
  const graph::Json saved = graph::graphToJson(g);
  EXPECT_EQ(saved["nodes"]["in_tet"]["typeVersion"], 2);
  const graph::Graph fresh = graph::parseGraph(
      R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
        "p": {"type": "PointConstraint", "typeVersion": 2, "params": {}}}, "links": []})",
      test::builtinNodes(), "new.tfd.json");
  EXPECT_EQ(std::get<std::string>(fresh.param("p", "support")), "auto");
}

TEST(NodeMigrations, AnUnknownOldQuantityIsReportedNamingTheParameter) {
  const std::string text = R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "vdb": {"type": "ExportVDB", "typeVersion": 1, "params": {"quantities": "tensor, colour"}}},
    "links": []})";
  try {
    graph::parseGraph(text, test::builtinNodes(), "old.tfd.json");
    FAIL() << "loaded";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/nodes/vdb/params/quantities"), std::string::npos) << what;
    EXPECT_NE(what.find("\"eigenvectors\""), std::string::npos) << what;
  }
}

TEST(NodeMigrations, ATypeVersionNewerThanTheReaderIsRefused) {
  const std::string text = R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "vtu": {"type": "ExportVTU", "typeVersion": 3, "params": {}}}, "links": []})";
  try {
    graph::parseGraph(text, test::builtinNodes(), "new.tfd.json");
    FAIL() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("typeVersion 3"), std::string::npos) << e.what();
  }
}

TEST(NodeMigrations, FormatVersion1FileWithEveryTypeLoads) {
  const char* path = TFD_TEST_DATA_DIR "/graphs/nodes/every_type_v1.tfd.json";
  const graph::Graph g = graph::loadGraphFile(path, test::builtinNodes());
  std::set<std::string> types;
  for (const auto& node : g.nodes()) types.insert(node.type().name());
  for (const graph::NodeType* t : test::builtinNodes().types()) {
    EXPECT_TRUE(types.count(t->name()))
        << "node type " << t->name() << " is missing from " << path
        << ": add a node of it at typeVersion 1 (format version 1: positions in \"layout\")";
  }
  // Meaning kept across both migrations (format 1 -> 2, typeVersion 1 -> 2).
  EXPECT_EQ(std::get<std::string>(g.param("vtu", "encoding")), "appended");
  EXPECT_EQ(std::get<Strings>(g.param("vdb", "quantities")), (Strings{"tensor", "eigenvalues"}));
  EXPECT_EQ(std::get<Strings>(g.param("exr", "quantities")), (Strings{"eigenvectors"}));
  EXPECT_EQ(std::get<std::string>(g.param("curves", "boundary_curves")), "drop");
  const graph::Json saved = graph::graphToJson(g);
  EXPECT_EQ(saved["formatVersion"], 2);
  EXPECT_EQ(saved["nodes"]["smooth"]["ui"]["position"], graph::Json::parse("[750, 180]"));
  EXPECT_FALSE(saved.contains("layout"));
  const std::string text = graph::graphToText(g);
  EXPECT_EQ(graph::graphToText(graph::parseGraph(text, test::builtinNodes(), "saved")), text);
}

TEST(NodeMigrations, EveryTypeVersionOfEveryTypeHasAFixtureThatLoads) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (const char* dir : {TFD_TEST_DATA_DIR "/graphs/nodes", TFD_TEST_DATA_DIR "/graphs/migrations",
                          TFD_SOURCE_DIR "/examples"}) {
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().string().ends_with(".tfd.json")) files.push_back(entry.path());
  }
  std::map<std::string, std::set<int>> seen;
  for (const fs::path& file : files) {
    EXPECT_NO_THROW(graph::loadGraphFile(file, test::builtinNodes())) << file;
    std::ifstream in(file);
    const graph::Json doc = graph::Json::parse(in);
    for (const auto& [name, node] : doc["nodes"].items())
      seen[node["type"].get<std::string>()].insert(node["typeVersion"].get<int>());
  }
  for (const graph::NodeType* t : test::builtinNodes().types()) {
    for (int v = 1; v <= t->version(); ++v) {
      EXPECT_TRUE(seen[t->name()].count(v))
          << t->name() << " typeVersion " << v
          << " has no fixture: add a node of it to a file in tests/data/graphs/nodes/ (or "
             "migrations/ for a migration with its own test)";
    }
  }
}

}  // namespace
}  // namespace tfd::nodes
