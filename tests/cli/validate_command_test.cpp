// `tfd validate`: every problem of a file, not only the first (unknown node types, bad and
// unknown parameters, bad and type-mismatched links, cycles, unconnected inputs), each naming
// its node and parameter; several files per call; the --json report; an unknown subcommand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

bool has(const std::string& text, const std::string& needle) {
  return text.find(needle) != std::string::npos;
}

ordered_json node(const std::string& type, ordered_json params = ordered_json::object(),
                  int version = 1) {
  return {{"type", type}, {"typeVersion", version}, {"params", std::move(params)}};
}

/// Seven problems, each of another kind.
ordered_json brokenGraph() {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"ball", node("TetMesh", {{"target_tets", -5}})},     // 1 out of range
                {"warp", node("NoSuchNodeType")},                     // 2 unknown type
                {"field", node("Propagate", {{"nope", 1}})},          // 3 unknown parameter
                {"topology", node("ExtractDegenerateCurves")},        //
                {"s1", node("LocalSmooth")},                          //
                {"s2", node("LocalSmooth")},                          //
                {"vtu", node("ExportVTU", {{"path", "a.vdb"}}, 2)}};  // 4 wrong extension
  g["links"] = {{{"from", "ball.mesh"}, {"to", "field.mesh"}},        // fine
                {{"from", "ball.mesh"}, {"to", "topology.field"}},    // 5 type mismatch
                {{"from", "warp.out"}, {"to", "vtu.field"}},          // skipped: warp did not load
                {{"from", "field.field"}, {"to", "s1.field"}},
                {{"from", "s1.field"}, {"to", "s2.field"}},
                {{"from", "s2.field"}, {"to", "s1.field"}}};  // 6 a second link into s1.field
  // 7: topology.field and vtu.field are required and end up unconnected.
  return g;
}

class Validate : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  }
  fs::path write(const ordered_json& graph, const std::string& name) {
    const fs::path path = dir.path() / name;
    std::ofstream(path) << graph.dump(2);
    return path;
  }
  TempDir dir{"validate"};
};

TEST_F(Validate, ReportsEveryProblemNotOnlyTheFirst) {
  const fs::path file = write(brokenGraph(), "broken.tfd.json");
  const CliRun r = runCli("validate " + shellQuote(file.string()));
  EXPECT_EQ(r.exitCode, 2);
  const std::string f = file.string();
  for (const std::string& line :
       {f + " at /nodes/ball/params/target_tets: ", f + " at /nodes/warp/type: unknown node type",
        f + " at /nodes/field/params/nope: unknown parameter \"nope\"",
        f + " at /nodes/vtu/params/path: ",
        f + " at /links/1: cannot link ball.mesh -> topology.field",
        f + " at /links/5: ", f + " at /nodes/topology: required input 'field' is not connected",
        f + " at /nodes/vtu: required input 'field' is not connected"})
    EXPECT_TRUE(has(r.err, "tfd: " + line)) << line << "\n" << r.err;
  EXPECT_FALSE(has(r.err, "/links/2")) << "a link of a node that did not load is not reported";
  EXPECT_TRUE(has(r.err, f + ": ")) << r.err;
  EXPECT_TRUE(has(r.err, " problems")) << "a count closes the list: " << r.err;
}

TEST_F(Validate, ACycleIsReportedWithTheOtherProblems) {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"s1", node("RemoveCurves")},
                {"s2", node("RemoveCurves")},
                {"bad", node("TetMesh", {{"quality", "high"}})}};
  g["links"] = {{{"from", "s1.field"}, {"to", "s2.field"}},
                {{"from", "s2.field"}, {"to", "s1.field"}}};
  const CliRun r = runCli("validate " + shellQuote(write(g, "cycle.tfd.json").string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "at /links/1: ")) << r.err;
  EXPECT_TRUE(has(r.err, "cycle")) << r.err;
  EXPECT_TRUE(has(r.err, "at /nodes/bad/params/quality: ")) << r.err;
}

TEST_F(Validate, SeveralFilesPerCallAndAJsonReport) {
  const fs::path good = write({{"format", "tfd-graph"},
                               {"formatVersion", 2},
                               {"nodes", {{"ball", node("TetMesh")}}},
                               {"links", ordered_json::array()}},
                              "good.tfd.json");
  const fs::path bad = write(brokenGraph(), "bad.tfd.json");
  const fs::path missing = dir.path() / "missing.tfd.json";
  CliRun r = runCli("validate " + shellQuote(good.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  r = runCli("validate " + shellQuote(good.string()) + " " + shellQuote(bad.string()) + " " +
             shellQuote(missing.string()));
  EXPECT_EQ(r.exitCode, 2) << "any file failing fails the call";
  EXPECT_TRUE(has(r.out, "ok: " + good.string())) << r.out;
  EXPECT_TRUE(has(r.err, "tfd: " + missing.string() + ": cannot read")) << r.err;

  r = runCli("validate --json " + shellQuote(good.string()) + " " + shellQuote(bad.string()) + " " +
             shellQuote(missing.string()));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "") << "--json: the report is the only output";
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["format"], "tfd-validate");
  EXPECT_EQ(report["formatVersion"], 1);
  EXPECT_EQ(report["ok"], false);
  ASSERT_EQ(report["files"].size(), 3u);
  const auto& g = report["files"][0];
  EXPECT_EQ(g["file"], good.string());
  EXPECT_EQ(g["ok"], true);
  EXPECT_EQ(g["formatVersion"], 2);
  EXPECT_TRUE(g["problems"].empty());
  const auto& b = report["files"][1];
  EXPECT_EQ(b["ok"], false);
  ASSERT_GE(b["problems"].size(), 8u) << b.dump(2);
  auto at = [&](const std::string& pointer) {
    for (const auto& p : b["problems"])
      if (p["pointer"] == pointer) return p;
    ADD_FAILURE() << "no problem at " << pointer << " in " << b.dump(2);
    return nlohmann::json::object();
  };
  const auto first = b["problems"][0];
  EXPECT_EQ(first["severity"], "error");
  EXPECT_EQ(first["node"], "ball");
  EXPECT_EQ(first["parameter"], "target_tets");
  EXPECT_EQ(first["pointer"], "/nodes/ball/params/target_tets");
  EXPECT_TRUE(first["message"].is_string());
  EXPECT_EQ(at("/nodes/warp/type")["node"], "warp");
  EXPECT_TRUE(at("/nodes/warp/type")["parameter"].is_null());
  EXPECT_EQ(at("/nodes/field/params/nope")["parameter"], "nope");
  EXPECT_EQ(at("/nodes/vtu/params/path")["node"], "vtu");
  EXPECT_EQ(at("/nodes/vtu/params/path")["parameter"], "path");
  EXPECT_EQ(at("/links/1")["node"], "topology") << "a link's problem names its target node";
  const auto& m = report["files"][2];
  EXPECT_EQ(m["ok"], false);
  EXPECT_TRUE(m["formatVersion"].is_null());
  ASSERT_EQ(m["problems"].size(), 1u);
  EXPECT_TRUE(m["problems"][0]["node"].is_null());
}

TEST_F(Validate, AnUnknownCommandIsNamedAndTheCommandsListed) {
  const CliRun r = runCli("frobnicate x.tfd.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err,
                  "tfd: unknown command \"frobnicate\" (commands: cook, validate, nodes, "
                  "info, upgrade, render)"))
      << r.err;
  EXPECT_EQ(runCli("validate --help").exitCode, 0) << "known commands still parse";
}

}  // namespace
}  // namespace tfd::test
