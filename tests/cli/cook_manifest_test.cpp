// The cook manifest tfd-cook.json and the progress lines without a terminal: a completed cook
// lists exactly the files it wrote (with their sizes) and every node's key; a failing cook
// says "failed" and names the node; progress says when each node starts and ends and, for a
// long step, repeats a line while it runs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "core/surface/primitives.h"
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

ordered_json designGraph() {
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {{"ball", node("TetMesh", {{"target_tets", 3000}})},
                {"wedge", node("PointConstraint", {{"kind", "degenerate"},
                                                   {"position", {-0.3, 0.05, 0.02}},
                                                   {"type", "linear"},
                                                   {"pattern", "wedge"}})},
                {"field", node("Propagate")},
                {"topology", node("ExtractDegenerateCurves")},
                {"vtu", node("ExportVTU", {{"path", "field.vtu"}})},
                {"exr", node("ExportEXR", {{"path", "slices/f.%03d.exr"}, {"voxel_size", 0.25}})},
                {"curves", node("ExportCurves", {{"path", "curves.json"}})}};
  g["links"] = {{{"from", "ball.mesh"}, {"to", "field.mesh"}},
                {{"from", "wedge.constraints"}, {"to", "field.constraints"}},
                {{"from", "field.field"}, {"to", "topology.field"}},
                {{"from", "field.field"}, {"to", "vtu.field"}},
                {{"from", "field.field"}, {"to", "exr.field"}},
                {{"from", "topology.curves"}, {"to", "curves.curves"}}};
  return g;
}

class CookManifest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  }
  fs::path write(const ordered_json& g) {
    std::ofstream(graph) << g.dump(2);
    return graph;
  }
  CliRun cook(const std::string& extra) {
    return runCli("cook " + shellQuote(graph.string()) + " " + extra);
  }
  static ordered_json manifestIn(const fs::path& folder) {
    return ordered_json::parse(bytesOf(folder / "tfd-cook.json"));
  }
  TempDir dir{"cook-manifest"};
  fs::path graph = dir.path() / "g.tfd.json";
};

TEST_F(CookManifest, ACompletedCookListsExactlyTheFilesItWrote) {
  write(designGraph());
  const fs::path out = dir.path() / "out";
  const CliRun r = cook("--out " + shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ordered_json m = manifestIn(out);
  EXPECT_EQ(m["format"], "tfd-cook");
  EXPECT_EQ(m["status"], "complete");
  EXPECT_EQ(m["graph"]["path"], graph.string());
  EXPECT_TRUE(std::regex_match(m["graph"]["hash"].get<std::string>(), std::regex("[0-9a-f]{32}")));
  // Exactly the files on disk (but the manifest), with their sizes.
  std::map<std::string, std::uintmax_t> onDisk, listed;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.is_regular_file() && e.path().filename() != "tfd-cook.json")
      onDisk[fs::weakly_canonical(e.path()).string()] = e.file_size();
  for (const auto& f : m["files"]) {
    EXPECT_EQ(f["written"], true);
    listed[fs::weakly_canonical(f["path"].get<std::string>()).string()] = f["size"];
  }
  EXPECT_EQ(listed, onDisk);
  EXPECT_GE(onDisk.size(), 3u) << "field.vtu, curves.json and the EXR slices";
  ASSERT_EQ(m["nodes"].size(), 7u);
  for (const auto& n : m["nodes"]) {
    EXPECT_EQ(n["state"], "cooked") << n.dump();
    EXPECT_TRUE(std::regex_match(n["key"].get<std::string>(), std::regex("[0-9a-f]{32}")));
  }
  // The same graph hashes alike; an override changes the hash (and the nodes' keys below it).
  ASSERT_EQ(cook("--out " + shellQuote(out.string())).exitCode, 0);
  EXPECT_EQ(manifestIn(out)["graph"]["hash"], m["graph"]["hash"]);
  ASSERT_EQ(cook("--out " + shellQuote(out.string()) + " --set curves.path=c2.json").exitCode, 0);
  const ordered_json changed = manifestIn(out);
  EXPECT_NE(changed["graph"]["hash"], m["graph"]["hash"]);
  EXPECT_EQ(changed["graph"]["sets"], ordered_json::array({"curves.path=c2.json"}));
}

TEST_F(CookManifest, AFailingCookSaysFailedAndNamesTheNode) {
  ordered_json g = designGraph();
  g["nodes"]["wedge"]["params"]["position"] = {5, 5, 5};  // outside the ball
  write(g);
  const CliRun r = cook("");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  const ordered_json m = manifestIn(dir.path());  // default out folder: the graph's
  EXPECT_EQ(m["status"], "failed");
  ASSERT_EQ(m["failed"].size(), 1u) << m.dump(2);
  EXPECT_EQ(m["failed"][0]["node"], "field");
  EXPECT_EQ(m["failed"][0]["type"], "Propagate");
  EXPECT_TRUE(has(m["failed"][0]["message"].get<std::string>(), "outside")) << m.dump(2);
  EXPECT_TRUE(m["files"].empty()) << "nothing downstream of the failure was written";
}

/// A sphere with one vertex far away: TetGen's refinement of it does not end for minutes.
void writeFarVertexSphere(const fs::path& path) {
  core::SurfaceMesh s = core::makeSphere(1, 0.5);
  s.positions[s.positions.size() / 2] *= 1e5;
  std::ofstream out(path);
  out.precision(17);
  for (const auto& p : s.positions) out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : s.triangles)
    out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

TEST_F(CookManifest, WithoutATerminalALinePerNodeStartAndEndAndWhileALongStepRuns) {
  // TetGen reports no fraction and, on this surface, runs until its 1 s time limit.
  writeFarVertexSphere(dir.path() / "far.obj");
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {
      {"m", node("TetMesh", {{"file", "far.obj"}, {"target_tets", 300}, {"time_limit", 1.0}})}};
  g["links"] = ordered_json::array();
  write(g);
  const CliRun r = cook("--progress-interval 0.2");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  std::istringstream lines(r.err);
  std::vector<std::string> progress;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("tfd: ", 0) != 0) progress.push_back(line);
  ASSERT_GE(progress.size(), 4u) << r.err;
  EXPECT_EQ(progress.front(), "start m (TetMesh)");
  // TetMesh says "5% TetGen" as TetGen starts, then nothing until it ends: no estimate from a
  // fraction that does not move.
  const std::regex running(R"(^\.\.\. m \(TetMesh\) running \d+ s(, \d+% TetGen)?$)");
  for (std::size_t i = 1; i + 1 < progress.size(); ++i)
    EXPECT_TRUE(std::regex_match(progress[i], running)) << progress[i];
  EXPECT_GE(progress.size() - 2, 3u) << "a line every 0.2 s of a 1 s step: " << r.err;
  EXPECT_TRUE(std::regex_match(progress.back(),
                               std::regex(R"(^\[1/1\] failed m \(TetMesh\) \d+\.\d{3} s$)")))
      << progress.back();
  EXPECT_EQ(manifestIn(dir.path())["failed"][0]["node"], "m");
}

TEST_F(CookManifest, OnATerminalTheBarNamesTheRunningNodeWithASpinnerAndItsTime) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  writeFarVertexSphere(dir.path() / "far.obj");
  ordered_json g = {{"format", "tfd-graph"}, {"formatVersion", 2}};
  g["nodes"] = {
      {"m", node("TetMesh", {{"file", "far.obj"}, {"target_tets", 300}, {"time_limit", 0.8}})}};
  g["links"] = ordered_json::array();
  write(g);
  // script(1) runs tfd on a pseudo-terminal, so stderr is a TTY.
  const fs::path typescript = dir.path() / "tty.txt";
  const std::string command = std::string(TFD_CLI_PATH) + " cook " + shellQuote(graph.string());
  const std::string run = "script -qec " + shellQuote(command) + " /dev/null >" +
                          shellQuote(typescript.string()) + " 2>&1 </dev/null";
  (void)std::system(run.c_str());
  const std::string text = bytesOf(typescript);
  // Redrawn lines "\r\033[K[<bar>] 0/1 m (TetMesh) 5% TetGen  0.3 s": the running node, a
  // spinner in the bar while TetGen reports no fraction, and the elapsed time.
  const std::regex bar(R"(\r\x1b\[K\[([= |/\\-]*)\] 0/1 m \(TetMesh\)( 5% TetGen)?  \d+\.\d s)");
  std::set<std::string> spinners;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), bar); it != std::sregex_iterator();
       ++it)
    spinners.insert((*it)[1].str());
  EXPECT_GE(spinners.size(), 3u) << "the spinner turns while nothing is reported:\n" << text;
  EXPECT_FALSE(has(text, "left")) << "no estimate from a fraction that does not move";
}

}  // namespace
}  // namespace tfd::test
