// `tfd cook --cache DIR` end to end with the real node types: a second process with one
// export parameter changed runs neither TetGen (TetMesh) nor the solve (Propagate); values
// read back from disk (a field with its mesh, curves) give byte-identical files; a damaged
// entry is cooked again with a warning, and the files are still byte-identical to an uncached
// cook.
#include <gtest/gtest.h>

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
                {"curves", node("ExportCurves", {{"path", "curves.json"}})}};
  g["links"] = {{{"from", "ball.mesh"}, {"to", "field.mesh"}},
                {{"from", "wedge.constraints"}, {"to", "field.constraints"}},
                {{"from", "field.field"}, {"to", "topology.field"}},
                {{"from", "field.field"}, {"to", "vtu.field"}},
                {{"from", "topology.curves"}, {"to", "vtu.curves"}},
                {{"from", "topology.curves"}, {"to", "curves.curves"}}};
  return g;
}

class CookCache : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
    std::ofstream(graph) << designGraph().dump(2);
  }
  CliRun cook(const fs::path& out, const std::string& extra) {
    CliRun r = runCli("cook " + shellQuote(graph.string()) + " --out " + shellQuote(out.string()) +
                      " " + extra);
    r.out = r.err + r.out;  // progress lines and warnings (stderr), then profile lines
    return r;
  }
  std::string withCache() const { return "--cache " + shellQuote(cache.string()); }
  /// The cache entry of a node, by the key the cook manifest names.
  fs::path entryOf(const fs::path& out, const std::string& name) {
    const auto manifest = nlohmann::json::parse(bytesOf(out / "tfd-cook.json"));
    for (const auto& n : manifest["nodes"])
      if (n["node"] == name) return cache / (n["key"].get<std::string>() + ".tfdc");
    return {};
  }

  TempDir dir{"cook-cache"};
  fs::path graph = dir.path() / "g.tfd.json";
  fs::path cache = dir.path() / "cache";
};

TEST_F(CookCache, AChangedExportParameterRunsNeitherTetgenNorTheSolve) {
  const fs::path out = dir.path() / "out";
  const CliRun first = cook(out, withCache() + " --profile");
  ASSERT_EQ(first.exitCode, 0) << first.out;
  EXPECT_TRUE(has(first.out, "profile ball TetMesh ")) << first.out;
  EXPECT_TRUE(has(first.out, "profile field Propagate ")) << first.out;

  const CliRun second = cook(out, withCache() + " --profile --set curves.path=curves2.json");
  ASSERT_EQ(second.exitCode, 0) << second.out;
  EXPECT_TRUE(has(second.out, "cached (disk) ball (TetMesh)")) << second.out;
  EXPECT_TRUE(has(second.out, "cached (disk) field (Propagate)")) << second.out;
  EXPECT_TRUE(has(second.out, "cached (disk) vtu (ExportVTU)")) << "its file is unchanged";
  EXPECT_FALSE(has(second.out, "profile ball ")) << second.out;
  EXPECT_FALSE(has(second.out, "profile field ")) << second.out;
  EXPECT_FALSE(has(second.out, "profile topology ")) << second.out;
  EXPECT_TRUE(has(second.out, "profile curves ExportCurves ")) << second.out;
  EXPECT_EQ(bytesOf(out / "curves2.json"), bytesOf(out / "curves.json"));
  EXPECT_TRUE(has(second.out, "info: node \"field\": ")) << "messages come back from disk";
}

TEST_F(CookCache, ValuesReadFromDiskOrDamagedEntriesGiveTheSameFiles) {
  const fs::path out = dir.path() / "out", plain = dir.path() / "plain";
  ASSERT_EQ(cook(out, withCache()).exitCode, 0);
  // vtu cooks again from the field (with its mesh) and the curves read back from disk.
  const CliRun fromDisk = cook(out, withCache() + " --profile --set vtu.path=again.vtu");
  ASSERT_EQ(fromDisk.exitCode, 0) << fromDisk.out;
  EXPECT_FALSE(has(fromDisk.out, "profile field ")) << fromDisk.out;
  EXPECT_TRUE(has(fromDisk.out, "profile vtu ")) << fromDisk.out;
  const CliRun uncached = cook(plain, "--set vtu.path=again.vtu");
  ASSERT_EQ(uncached.exitCode, 0) << uncached.out;
  ASSERT_TRUE(fs::is_regular_file(plain / "again.vtu"));
  EXPECT_EQ(bytesOf(out / "again.vtu"), bytesOf(plain / "again.vtu"));

  // Flip one byte in the payload of Propagate's entry: the field is cooked again (its mesh
  // read from disk), with a warning, and the file is still identical.
  const fs::path entry = entryOf(out, "field");
  ASSERT_TRUE(fs::is_regular_file(entry)) << entry;
  std::string bytes = bytesOf(entry);
  bytes[bytes.size() - 100] ^= 0x01;
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
  const CliRun damaged = cook(out, withCache() + " --profile --set vtu.path=third.vtu");
  ASSERT_EQ(damaged.exitCode, 0) << damaged.out;
  EXPECT_TRUE(has(damaged.out, "tfd: warning: cache: cache entry " + entry.string() +
                                   " is damaged (checksum mismatch in its values)"))
      << damaged.out;
  EXPECT_TRUE(has(damaged.out, "profile field Propagate ")) << damaged.out;
  EXPECT_FALSE(has(damaged.out, "profile ball ")) << "the mesh still comes from disk";
  EXPECT_EQ(bytesOf(out / "third.vtu"), bytesOf(plain / "again.vtu"));

  // Truncated: the same.
  fs::resize_file(entryOf(out, "field"), 100);
  const CliRun truncated = cook(out, withCache() + " --profile --set vtu.path=fourth.vtu");
  ASSERT_EQ(truncated.exitCode, 0) << truncated.out;
  EXPECT_TRUE(has(truncated.out, "does not match its header")) << truncated.out;
  EXPECT_EQ(bytesOf(out / "fourth.vtu"), bytesOf(plain / "again.vtu"));
}

TEST_F(CookCache, BadCacheOptionsAreUsageErrors) {
  std::ofstream(dir.path() / "file") << "x";
  const CliRun notDir = cook(dir.path() / "out", "--cache " + (dir.path() / "file").string());
  EXPECT_EQ(notDir.exitCode, 2) << notDir.out;
  EXPECT_TRUE(has(notDir.out, "cannot create the folder")) << notDir.out;
  const CliRun badSize = cook(dir.path() / "out", withCache() + " --cache-size lots");
  EXPECT_EQ(badSize.exitCode, 2) << badSize.out;
}

}  // namespace
}  // namespace tfd::test
