// docs/nodes.md is the output of `tfd nodes --markdown`: fails when a node declaration changed
// and the reference was not regenerated.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/cli_runner.h"

namespace tfd::test {
namespace {

TEST(NodesDoc, DocsNodesMdMatchesTheRegistry) {
  if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  const std::filesystem::path doc = std::filesystem::path(TFD_SOURCE_DIR) / "docs" / "nodes.md";
  std::ifstream in(doc);
  ASSERT_TRUE(in) << doc << " is missing; generate it with: tfd nodes --markdown > docs/nodes.md";
  std::stringstream committed;
  committed << in.rdbuf();
  const CliRun r = runCli("nodes --markdown");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, committed.str())
      << "docs/nodes.md is out of date; regenerate it with: build/apps/tfd nodes --markdown > "
         "docs/nodes.md";
}

}  // namespace
}  // namespace tfd::test
