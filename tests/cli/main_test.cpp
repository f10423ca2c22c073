// End-to-end tests of the `tfd` binary that need no node types: exit codes and messages for
// usage errors, load errors, empty graphs, `nodes --json`, `info` and `upgrade`.
// (Tests that cook real nodes — a good graph, a failing node, --set, --profile — are added
// once node types are registered.)
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_runner.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
const fs::path kGraphs = fs::path(TFD_TEST_DATA_DIR) / "graphs";

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
    dir = fs::temp_directory_path() / ("tfd_cli_test_" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  static std::string q(const fs::path& p) { return shellQuote(p.string()); }
  static bool has(const std::string& text, const std::string& needle) {
    return text.find(needle) != std::string::npos;
  }
  fs::path dir;
};

TEST_F(Cli, UsageErrorsExitTwo) {
  CliRun r = runCli("");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "tfd: A subcommand is required")) << r.err;
  EXPECT_EQ(runCli("frobnicate").exitCode, 2);
  EXPECT_EQ(runCli("cook").exitCode, 2) << "missing GRAPH";
  r = runCli("cook " + q(kGraphs / "cli" / "empty.tfd.json") + " --threads 0");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "--threads")) << r.err;
  EXPECT_EQ(runCli("upgrade " + q(kGraphs / "v1_empty.tfd.json")).exitCode, 2) << "missing -o";
  r = runCli("--help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(has(r.out, "cook")) << r.out;
  r = runCli("--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(has(r.out, "tfd ")) << r.out;
}

TEST_F(Cli, MissingFileExitsTwoNamingIt) {
  const fs::path missing = dir / "missing.tfd.json";
  for (const char* command : {"cook", "validate", "info"}) {
    SCOPED_TRACE(command);
    const CliRun r = runCli(std::string(command) + " " + q(missing));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(has(r.err, "tfd: " + missing.string())) << r.err;
  }
  EXPECT_TRUE(has(runCli("cook " + q(missing)).err, "cannot read: No such file or directory"));
}

TEST_F(Cli, MalformedFileExitsTwoWithLineAndColumn) {
  const CliRun r = runCli("cook " + q(kGraphs / "cli" / "malformed.tfd.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "malformed.tfd.json: invalid JSON: parse error at line 3, column 1"))
      << r.err;
  EXPECT_EQ(runCli("validate " + q(kGraphs / "cli" / "malformed.tfd.json")).exitCode, 2);
}

TEST_F(Cli, UnknownNodeTypeExitsTwoNamingTypeAndPlace) {
  const CliRun r = runCli("cook " + q(kGraphs / "cli" / "unknown_type.tfd.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err,
                  "unknown_type.tfd.json at /nodes/warp1/type: unknown node type "
                  "\"NoSuchNodeType\""))
      << r.err;
}

TEST_F(Cli, VersionProblemsExitTwo) {
  CliRun r = runCli("validate " + q(kGraphs / "cli" / "newer.tfd.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "at /formatVersion: format version 99 is newer than this tfd")) << r.err;
  r = runCli("validate " + q(kGraphs / "cli" / "no_version.tfd.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "at /formatVersion: missing")) << r.err;
}

TEST_F(Cli, EmptyGraphCooksAndValidates) {
  const fs::path graph = kGraphs / "cli" / "empty.tfd.json";
  CliRun r = runCli("cook " + q(graph) + " --out " + q(dir / "out") + " --threads 1 --profile");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_directory(dir / "out")) << "--out is created";
  EXPECT_EQ(r.out, "") << "no node cooked: no profile lines";
  // --out always: the default (the graph's folder) would put a cook manifest in the sources.
  r = runCli("cook " + q(graph) + " --out " + q(dir / "out") + " --quiet");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.err, "") << "--quiet prints nothing but errors";
  r = runCli("validate " + q(graph));
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(has(r.out, "ok: ")) << r.out;
}

TEST_F(Cli, SetOnUnknownNodeOrMalformedSetExitsTwo) {
  const fs::path graph = kGraphs / "cli" / "empty.tfd.json";
  CliRun r = runCli("cook " + q(graph) + " --set p1.radius=2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "tfd: --set p1.radius=2: unknown node \"p1\"")) << r.err;
  r = runCli("cook --set radius=2 " + q(graph));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "expected NODE.PARAM=VALUE")) << r.err;
  r = runCli("cook " + q(graph) + " --node nope");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "unknown node \"nope\"")) << r.err;
}

TEST_F(Cli, NodesJsonParses) {
  const CliRun r = runCli("nodes --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "tfd-node-types");
  ASSERT_TRUE(j["nodeTypes"].is_array());
  for (const auto& t : j["nodeTypes"]) {
    EXPECT_TRUE(t["type"].is_string());
    EXPECT_TRUE(t["params"].is_array());
  }
  const CliRun bad = runCli("nodes NoSuchNodeType");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_TRUE(has(bad.err, "unknown node type \"NoSuchNodeType\"")) << bad.err;
}

TEST_F(Cli, UpgradeWritesTheCurrentFormat) {
  const fs::path out = dir / "up.tfd.json";
  const CliRun r = runCli("upgrade " + q(kGraphs / "v1_empty.tfd.json") + " -o " + q(out));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream got(out), want(kGraphs / "v1_empty.upgraded.tfd.json");
  std::stringstream a, b;
  a << got.rdbuf();
  b << want.rdbuf();
  const nlohmann::json upgraded = nlohmann::json::parse(a.str());
  EXPECT_EQ(upgraded["formatVersion"], 2);
  EXPECT_FALSE(upgraded.contains("layout"));
  EXPECT_EQ(upgraded.dump(), nlohmann::json::parse(b.str()).dump());
  EXPECT_TRUE(has(r.out, "format version 1")) << r.out;
  // The upgraded file validates as current.
  const CliRun v = runCli("validate " + q(out));
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_TRUE(has(v.out, "format version 2")) << v.out;
}

TEST_F(Cli, InfoDescribesGraphFilesAndRefusesUnknownKinds) {
  CliRun r = runCli("info " + q(kGraphs / "v1_empty.tfd.json"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.out, "format: tfd-graph, version 1")) << r.out;
  EXPECT_TRUE(has(r.out, "status: loads")) << r.out;
  r = runCli("info " + q(kGraphs / "cli" / "unknown_type.tfd.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.out, "warp1  NoSuchNodeType v1")) << r.out;
  EXPECT_TRUE(has(r.err, "unknown node type")) << r.err;
  { std::ofstream(dir / "notes.xyz") << "hello"; }
  r = runCli("info " + q(dir / "notes.xyz"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "no describer")) << r.err;
}

TEST_F(Cli, NumbersBeyondTheDoubleRangeAreLoadErrorsNotAborts) {
  const fs::path graph = dir / "huge.tfd.json";
  std::ofstream(graph) << R"({"format": "tfd-graph", "formatVersion": 1e400, "nodes": {}})";
  for (const std::string command : {"validate ", "cook ", "info "}) {
    const CliRun r = runCli(command + q(graph));
    EXPECT_EQ(r.exitCode, 2) << command << r.err;
    EXPECT_TRUE(has(r.err, "huge.tfd.json at /formatVersion: the number '1e400' is beyond"))
        << command << r.err;
  }
  const CliRun r = runCli("upgrade " + q(graph) + " -o " + q(dir / "new.tfd.json"));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(has(r.err, "beyond the range of a double")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "new.tfd.json"));
}

}  // namespace
}  // namespace tfd::test
