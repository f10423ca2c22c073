// `tfd cook --files`: one line "file <node> <path>" per file the cook wrote (the evaluator's
// written-files list), exactly the files in the out folder; and the upstream-failure wording.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;

TEST(CookFiles, FilesLinesListExactlyTheFilesInTheOutFolder) {
  if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  TempDir dir("cook-files");
  const fs::path out = dir.path() / "out";
  const fs::path graph = fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json";
  const CliRun r =
      runCli("cook " + shellQuote(graph.string()) +
             " --set ball.target_tets=3000 --set vdb.voxel_size=0.08 --set exr.voxel_size=0.08"
             " -q --files --out " +
             shellQuote(out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::set<fs::path> listed;
  std::set<std::string> nodes;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    ASSERT_EQ(line.rfind("file ", 0), 0u) << "only file lines with -q --files: " << line;
    const std::size_t space = line.find(' ', 5);
    ASSERT_NE(space, std::string::npos) << line;
    nodes.insert(line.substr(5, space - 5));
    EXPECT_TRUE(listed.insert(line.substr(space + 1)).second) << "listed twice: " << line;
  }
  std::set<fs::path> present;
  for (const auto& e : fs::recursive_directory_iterator(out))  // but the cook manifest
    if (e.is_regular_file() && e.path().filename() != "tfd-cook.json") present.insert(e.path());
  EXPECT_EQ(listed, present);
  EXPECT_EQ(nodes, (std::set<std::string>{"vtu", "vdb", "exr", "curves_json", "curves_vtp"}));
}

}  // namespace
}  // namespace tfd::test
