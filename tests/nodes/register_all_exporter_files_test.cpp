// The real exporters are side-effect nodes: a cook of examples/default.tfd.json lists exactly
// the files it wrote, and within one Evaluator an exporter whose file was deleted or edited on
// disk cooks again (only it), while intact files are left alone.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

/// Every regular file under `dir`, as absolute paths, sorted.
std::set<fs::path> filesUnder(const fs::path& dir) {
  std::set<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out.insert(e.path());
  return out;
}

std::vector<std::string> cookedNodes(const graph::CookResult& r) {
  std::vector<std::string> out;
  for (const graph::NodeReport& rep : r.reports)
    if (rep.cookCalled) out.push_back(rep.node);
  return out;
}

TEST(ExporterFiles, EveryExporterDeclaresItselfASideEffectNode) {
  for (const char* type : {"ExportVTU", "ExportVDB", "ExportEXR", "ExportCurves"})
    EXPECT_TRUE(test::builtinNodes().get(type).decl().hasSideEffects()) << type;
  EXPECT_FALSE(test::builtinNodes().get("Propagate").decl().hasSideEffects());
}

TEST(ExporterFiles, DefaultExampleListsItsFilesAndReRunsOnlyTheExporterWhoseFileChanged) {
  test::TempDir dir("exporter-files");
  graph::Graph g = graph::loadGraphFile(fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json",
                                        test::builtinNodes());
  // Coarser than the example's mesh and voxels, to keep the test fast.
  g.setParam("ball", "target_tets", std::int64_t(3000));
  g.setParam("vdb", "voxel_size", 0.08);
  g.setParam("exr", "voxel_size", 0.08);
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;

  const graph::CookResult first = ev.cook(g, options);
  ASSERT_TRUE(first.ok());
  std::set<fs::path> listed;
  std::map<std::string, int> perNode;
  for (const graph::WrittenFile& f : first.writtenFiles()) {
    EXPECT_TRUE(listed.insert(f.path).second) << "listed twice: " << f.path;
    ++perNode[f.node];
  }
  EXPECT_EQ(listed, filesUnder(dir.path())) << "exactly the files in the out folder";
  EXPECT_EQ(perNode.at("vtu"), 1);
  EXPECT_EQ(perNode.at("vdb"), 1);
  EXPECT_GT(perNode.at("exr"), 8) << "one file per slice";
  EXPECT_EQ(perNode.size(), 5u);
  const fs::path vtu = first.report("vtu")->files.at(0).path;
  const fs::path vdb = first.report("vdb")->files.at(0).path;
  const fs::path slice = first.report("exr")->files.at(3).path;

  // Unchanged: nothing cooks and no file is rewritten.
  std::map<fs::path, fs::file_time_type> stamps;
  for (const fs::path& p : listed) stamps[p] = fs::last_write_time(p);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  graph::CookResult again = ev.cook(g, options);
  EXPECT_TRUE(cookedNodes(again).empty());
  EXPECT_TRUE(again.writtenFiles().empty());
  for (const auto& [p, t] : stamps) EXPECT_EQ(fs::last_write_time(p), t) << p;

  // A deleted file: only its exporter cooks, and writes it again.
  fs::remove(vdb);
  EXPECT_EQ(ev.dirtyNodes(g, options), std::vector<std::string>{"vdb"});
  again = ev.cook(g, options);
  EXPECT_EQ(cookedNodes(again), std::vector<std::string>{"vdb"});
  EXPECT_TRUE(fs::exists(vdb));
  EXPECT_EQ(again.writtenFiles(), (std::vector<graph::WrittenFile>{{"vdb", vdb}}));

  // A file edited on disk, and one slice of the EXR sequence removed.
  const auto vtuSize = fs::file_size(vtu);
  { std::ofstream(vtu, std::ios::app) << "<!-- edited -->\n"; }
  fs::remove(slice);
  again = ev.cook(g, options);
  EXPECT_EQ(cookedNodes(again), (std::vector<std::string>{"vtu", "exr"}));
  EXPECT_EQ(fs::file_size(vtu), vtuSize);
  EXPECT_TRUE(fs::exists(slice));
  EXPECT_EQ(filesUnder(dir.path()), listed);
}

}  // namespace
}  // namespace tfd::nodes
