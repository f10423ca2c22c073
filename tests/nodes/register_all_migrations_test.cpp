// Node typeVersion migrations of the registered types: files written before a parameter was
// renamed or changed kind load with the same meaning and save as the current version.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"

namespace tfd::nodes {
namespace {

const graph::NodeRegistry& registry() {
  static const graph::NodeRegistry& r = *[] {
    auto* out = new graph::NodeRegistry;  // lives as long as the test program
    registerAll(*out);
    return out;
  }();
  return r;
}

using Strings = std::vector<std::string>;
const char* kFixture = TFD_TEST_DATA_DIR "/graphs/migrations/exporters_v1.tfd.json";

TEST(NodeMigrations, ExportersOfTypeVersion1KeepTheirMeaning) {
  const graph::Graph g = graph::loadGraphFile(kFixture, registry());
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
  const graph::Graph g = graph::loadGraphFile(kFixture, registry());
  const graph::Json saved = graph::graphToJson(g);
  for (const char* node : {"vtu", "vdb", "exr"}) {
    EXPECT_EQ(saved["nodes"][node]["typeVersion"], 2) << node;
    EXPECT_FALSE(saved["nodes"][node]["params"].contains("quantity")) << node;
  }
  EXPECT_EQ(saved["nodes"]["exr"]["params"]["quantities"],
            graph::Json::parse(R"(["eigenvalues"])"));
  const std::string text = graph::graphToText(g);
  const graph::Graph again = graph::parseGraph(text, registry(), "saved");
  EXPECT_EQ(graph::graphToText(again), text);
}

TEST(NodeMigrations, AnUnknownOldQuantityIsReportedNamingTheParameter) {
  const std::string text = R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "vdb": {"type": "ExportVDB", "typeVersion": 1, "params": {"quantities": "tensor, colour"}}},
    "links": []})";
  try {
    graph::parseGraph(text, registry(), "old.tfd.json");
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
    graph::parseGraph(text, registry(), "new.tfd.json");
    FAIL() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("typeVersion 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tfd::nodes
