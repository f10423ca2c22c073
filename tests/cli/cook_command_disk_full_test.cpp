// A full disk during an export, simulated with a file-size limit (`ulimit -f`, RLIMIT_FSIZE):
// every exporter must fail its node (exit 1) naming the target file and the reason, keep the
// older file at that path byte for byte, and leave no hidden temporary behind. tfd ignores
// SIGXFSZ, so the limit shows up as a failed write (EFBIG) exactly like ENOSPC would.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string slurp(const fs::path& p) { return bytesOf(p); }

ordered_json node(const std::string& type, ordered_json params = ordered_json::object()) {
  return {{"type", type}, {"typeVersion", 1}, {"params", std::move(params)}};
}

/// A ball with a field from an expression and one exporter `type` writing `path`.
ordered_json exportGraph(const std::string& type, ordered_json params) {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"ball", node("TetMesh", {{"target_tets", 3000}})},
                {"field", node("FieldExpression", {{"xx", "x*x"}, {"yy", "-y"}, {"xy", "z"}})},
                {"out", node(type, std::move(params))}};
  g["links"] = {{{"from", "ball.mesh"}, {"to", "field.mesh"}},
                {{"from", "field.field"}, {"to", "out.field"}}};
  return g;
}

struct LimitedRun {
  int exitCode = -1;
  std::string err;
};

/// `tfd cook graph` under `ulimit -f blocks` (1024-byte blocks; 0: no limit).
LimitedRun cookLimited(const fs::path& graph, int blocks) {
  const fs::path err = graph.string() + ".err";
  std::string command = "(";
  if (blocks > 0) command += "ulimit -f " + std::to_string(blocks) + " && ";
  command += "exec " + shellQuote(TFD_CLI_PATH) + " cook --quiet " + shellQuote(graph.string()) +
             ") >/dev/null 2>" + shellQuote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  LimitedRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.err = slurp(err);
  fs::remove(err);
  return run;
}

class DiskFull : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  }
  TempDir dir{std::string("disk-full-") + GetParam()};
};

TEST_P(DiskFull, ExporterFailsAndKeepsTheOlderFile) {
  const std::string type = GetParam();
  ordered_json params;
  fs::path file;
  if (type == std::string("ExportVDB")) {
    file = "field.vdb";
    params = {{"path", file}, {"voxel_size", 0.2}};
  } else if (type == std::string("ExportVTU")) {
    file = "field.vtu";
    params = {{"path", file}, {"encoding", "ascii"}};
  } else {  // ExportEXR: one slice checked
    file = "slices/f.002.exr";
    params = {{"path", "slices/f.%03d.exr"}, {"voxel_size", 0.2}};
  }
  const fs::path graph = dir.path() / "g.tfd.json";
  std::ofstream(graph) << exportGraph(type, params).dump(2);
  const LimitedRun first = cookLimited(graph, 0);
  ASSERT_EQ(first.exitCode, 0) << first.err;
  const std::string old = bytesOf(dir.path() / file);
  ASSERT_GT(old.size(), 1000u);

  // A finer export needs a bigger file than the limit allows.
  ordered_json finer = params;
  if (finer.contains("voxel_size")) finer["voxel_size"] = 0.03;
  std::ofstream(graph) << exportGraph(type, finer).dump(2);
  const int limitBlocks = type == std::string("ExportVTU") ? 8 : 64;
  const LimitedRun full = cookLimited(graph, limitBlocks);
  EXPECT_EQ(full.exitCode, 1) << full.err;
  EXPECT_NE(full.err.find("tfd: node \"out\" (" + type + "): "), std::string::npos) << full.err;
  EXPECT_NE(full.err.find("File too large"), std::string::npos) << full.err;
  EXPECT_EQ(full.err.find(".tfd-tmp"), std::string::npos) << "names the target: " << full.err;
  EXPECT_TRUE(bytesOf(dir.path() / file) == old) << "the older file must be kept";
  for (const auto& e : fs::recursive_directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tfd-tmp"), std::string::npos) << e.path();
}

INSTANTIATE_TEST_SUITE_P(Exporters, DiskFull,
                         ::testing::Values("ExportVDB", "ExportVTU", "ExportEXR"));

}  // namespace
}  // namespace tfd::test
