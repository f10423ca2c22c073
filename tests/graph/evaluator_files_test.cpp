// Side-effect nodes in one long-lived Evaluator (the editor's case): an exporter whose file went
// missing or changed on disk cooks again although its cache key is unchanged, an intact file is
// left alone, and the cook result lists the files each cook wrote.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "graph/evaluator.h"
#include "tests/support/graph_test_nodes.h"
#include "tests/support/temp_dir.h"

namespace tfd::graph {
namespace {

namespace fs = std::filesystem;
using test::cookLog;

std::string contentOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class SideEffects : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    cookLog().clear();
    options.outDir = dir.path();
  }

  /// c(3) --> scale(x2) --> a (a.txt), b (b.txt, b.txt.1, b.txt.2)
  Graph exporters() {
    Graph g(registry);
    g.addNode("Constant", "c");
    g.setParam("c", "value", 3.0);
    g.addNode("Scale", "scale");
    g.addNode("WriteFile", "a");
    g.setParam("a", "path", std::string("a.txt"));
    g.addNode("WriteFile", "b");
    g.setParam("b", "path", std::string("b.txt"));
    g.setParam("b", "copies", std::int64_t(3));
    g.connect({"c", "out"}, {"scale", "in"});
    g.connect({"scale", "out"}, {"a", "in"});
    g.connect({"scale", "out"}, {"b", "in"});
    return g;
  }

  std::vector<std::string> cookedNodes() {
    std::vector<std::string> v = cookLog().nodes();
    std::sort(v.begin(), v.end());
    return v;
  }

  NodeRegistry registry;
  test::TempDir dir{"evaluator-files"};
  CookOptions options;
};

TEST_F(SideEffects, TheDeclarationSaysSoAndTheResultListsTheWrittenFilesInOrder) {
  EXPECT_TRUE(registry.get("WriteFile").decl().hasSideEffects());
  EXPECT_FALSE(registry.get("Sink").decl().hasSideEffects());
  Evaluator ev;
  const CookResult r = ev.cook(exporters(), options);
  ASSERT_TRUE(r.ok());
  const fs::path d = dir.path();
  EXPECT_EQ(
      r.writtenFiles(),
      (std::vector<WrittenFile>{
          {"a", d / "a.txt"}, {"b", d / "b.txt"}, {"b", d / "b.txt.1"}, {"b", d / "b.txt.2"}}));
  ASSERT_EQ(r.report("b")->files.size(), 3u);
  EXPECT_TRUE(r.report("b")->files[2].exists);
  EXPECT_EQ(r.report("b")->files[2].size, fs::file_size(d / "b.txt.2"));
  EXPECT_TRUE(r.report("scale")->files.empty());
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.txt", "b.txt", "b.txt.1", "b.txt.2"}));
}

TEST_F(SideEffects, AnUnchangedFileIsNotRewritten) {
  Evaluator ev;
  const Graph g = exporters();
  ASSERT_TRUE(ev.cook(g, options).ok());
  const auto before = fs::last_write_time(dir.path() / "a.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a rewrite would show in mtime
  cookLog().clear();
  EXPECT_TRUE(ev.dirtyNodes(g, options).empty());
  const CookResult r = ev.cook(g, options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(cookLog().total(), 0);
  EXPECT_EQ(r.report("a")->state, NodeState::Cached);
  EXPECT_FALSE(r.report("a")->filesChanged);
  EXPECT_EQ(r.report("a")->files.size(), 1u) << "a cached exporter still knows its files";
  EXPECT_TRUE(r.writtenFiles().empty()) << "this cook wrote nothing";
  EXPECT_EQ(fs::last_write_time(dir.path() / "a.txt"), before);
}

TEST_F(SideEffects, DeletingAnExportedFileReRunsOnlyThatExporter) {
  Evaluator ev;
  const Graph g = exporters();
  ASSERT_TRUE(ev.cook(g, options).ok());
  fs::remove(dir.path() / "b.txt.1");
  EXPECT_EQ(ev.dirtyNodes(g, options), (std::vector<std::string>{"b"}));
  cookLog().clear();
  const CookResult r = ev.cook(g, options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(cookedNodes(), (std::vector<std::string>{"b"}));
  EXPECT_EQ(r.report("b")->state, NodeState::Cooked);
  EXPECT_TRUE(r.report("b")->filesChanged);
  EXPECT_EQ(r.report("a")->state, NodeState::Cached);
  EXPECT_EQ(r.report("scale")->state, NodeState::Cached) << "upstream is not cooked again";
  EXPECT_EQ(contentOf(dir.path() / "b.txt.1"), "6\n");
  EXPECT_EQ(r.writtenFiles().size(), 3u);
  // The new stamps are kept: the next cook is free again.
  cookLog().clear();
  EXPECT_EQ(ev.cook(g, options).count(NodeState::Cached), 4u);
  EXPECT_EQ(cookLog().total(), 0);
}

TEST_F(SideEffects, AFileModifiedOnDiskReRunsItsExporter) {
  Evaluator ev;
  const Graph g = exporters();
  ASSERT_TRUE(ev.cook(g, options).ok());
  {
    std::ofstream out(dir.path() / "a.txt", std::ios::app);
    out << "edited by hand\n";
  }
  cookLog().clear();
  CookResult r = ev.cook(g, options);
  EXPECT_EQ(cookedNodes(), (std::vector<std::string>{"a"}));
  EXPECT_EQ(contentOf(dir.path() / "a.txt"), "6\n");

  // Same size, other content: the modification time tells.
  {
    std::ofstream out(dir.path() / "a.txt", std::ios::binary | std::ios::trunc);
    out << "7\n";
  }
  fs::last_write_time(dir.path() / "a.txt",
                      fs::last_write_time(dir.path() / "a.txt") + std::chrono::seconds(5));
  cookLog().clear();
  r = ev.cook(g, options);
  EXPECT_EQ(cookedNodes(), (std::vector<std::string>{"a"}));
  EXPECT_EQ(contentOf(dir.path() / "a.txt"), "6\n");
}

TEST_F(SideEffects, WritingAFileIsReservedToDeclaredSideEffectNodesThatReallyWroteIt) {
  NodeRegistry r;
  test::registerTestNodes(r);
  r.add(
      "Sneaky", 1, [](NodeDecl& d) { d.input<test::Number>("in"); },
      [](CookContext& c) { c.wroteFile("x.txt"); });
  r.add(
      "Boaster", 1,
      [](NodeDecl& d) {
        d.input<test::Number>("in").optional();
        d.sideEffect();
      },
      [](CookContext& c) { c.wroteFile(c.nodeName() + "-never-written.txt"); });
  Graph g(r);
  g.addNode("Constant", "c");
  g.addNode("Sneaky", "sneaky");
  g.addNode("Boaster", "boaster");
  g.connect({"c", "out"}, {"sneaky", "in"});
  Evaluator ev;
  const CookResult res = ev.cook(g, options);
  ASSERT_EQ(res.report("sneaky")->state, NodeState::Failed);
  EXPECT_EQ(res.report("sneaky")->messages.at(0).text,
            "node type Sneaky reported a written file but is not declared sideEffect()");
  EXPECT_EQ(res.report("sneaky")->messages.at(0).kind, MessageKind::CookFailed);
  ASSERT_EQ(res.report("boaster")->state, NodeState::Failed);
  EXPECT_NE(res.report("boaster")->messages.at(0).text.find("but there is no such file"),
            std::string::npos);
  EXPECT_TRUE(res.report("boaster")->files.empty());
  EXPECT_TRUE(res.writtenFiles().empty());
}

}  // namespace
}  // namespace tfd::graph
