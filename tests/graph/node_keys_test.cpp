// Every parameter feeds the cache key; names and editor data do not.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "graph/hash.h"
#include "graph/node_keys.h"
#include "tests/support/graph_test_nodes.h"
#include "tests/support/registry_hash_check.h"

namespace tfd::graph {
namespace {

TEST(ParamHash, EveryParameterOfEveryTestNodeTypeChangesTheHash) {
  NodeRegistry registry;
  test::registerTestNodes(registry);
  test::expectEveryParameterChangesHash(registry);
}

TEST(ParamHash, TheCheckCatchesAParameterLeftOutOfTheKey) {
  // perturbedValue must find a different valid value for each kind, or the check is blind.
  NodeRegistry registry;
  test::registerTestNodes(registry);
  for (const ParamDecl& p : registry.get("AllParams").decl().params()) {
    auto changed = test::perturbedValue(p, p.defaultValue);
    ASSERT_TRUE(changed.has_value()) << p.name;
    EXPECT_NE(*changed, p.defaultValue) << p.name;
    EXPECT_NO_THROW(checkParamValue(p, *changed)) << p.name;
  }
  ParamDecl single;
  single.name = "only";
  single.kind = ParamKind::String;
  single.choices = {"one"};
  single.defaultValue = std::string("one");
  EXPECT_FALSE(test::perturbedValue(single, single.defaultValue).has_value());
  ParamDecl tight;
  tight.name = "t";
  tight.kind = ParamKind::Double;
  tight.min = 1e-14;
  tight.max = 1e-2;
  tight.defaultValue = 1e-8;
  auto v = test::perturbedValue(tight, tight.defaultValue);
  ASSERT_TRUE(v.has_value());
  EXPECT_NO_THROW(checkParamValue(tight, *v));
}

TEST(ParamHash, KeysIgnoreNamesAndUiButSeeFilesAndOutputFolders) {
  namespace fs = std::filesystem;
  NodeRegistry registry;
  test::registerTestNodes(registry);
  const fs::path dir = fs::temp_directory_path() / ("tfd_keys_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Graph g(registry);
  g.setSourcePath(dir / "g.tfd.json");
  g.addNode("ReadText", "read");
  g.setParam("read", "path", std::string("in.txt"));
  g.addNode("Constant", "c");
  g.addNode("Sink", "sink");
  g.connect({"c", "out"}, {"sink", "in"});
  auto keyOf = [&](const std::string& node, const fs::path& out = {}) {
    return nodeKey(g, node, {makePathContext(g, out), true});
  };
  const Hash read0 = keyOf("read"), sink0 = keyOf("sink");
  g.renameNode("c", "constant");
  g.setUi("sink", Json::object({{"position", {3, 4}}}));
  EXPECT_EQ(keyOf("sink"), sink0);
  EXPECT_NE(keyOf("sink", dir / "elsewhere"), sink0) << "outputs resolve against --out";
  { std::ofstream(dir / "in.txt") << "now it exists"; }
  EXPECT_NE(keyOf("read"), read0) << "an input file's stamp is part of the key";
  const Hash withFile = keyOf("read");
  EXPECT_EQ(nodeKey(g, "read", {makePathContext(g), false}),
            nodeKey(g, "read", {makePathContext(g), false}));
  EXPECT_NE(nodeKey(g, "read", {makePathContext(g), false}), withFile);
  g.setSourcePath(dir / "sub" / "g.tfd.json");
  EXPECT_NE(keyOf("read"), withFile) << "relative inputs resolve against the graph's folder";
  fs::remove_all(dir);
}

TEST(Hasher, FramingAndStability) {
  EXPECT_NE(Hasher().add("ab").add("c").finish(), Hasher().add("a").add("bc").finish());
  EXPECT_NE(Hasher().add(1.0).finish(), Hasher().add(std::int64_t{1}).finish());
  EXPECT_NE(Hasher().add(true).finish(), Hasher().add(std::int64_t{1}).finish());
  EXPECT_EQ(Hasher().add(0.0).finish(), Hasher().add(-0.0).finish());
  EXPECT_NE(Hasher().add("").finish(), Hasher().finish());
  EXPECT_EQ(Hasher().add("tfd").add(3.5).finish(), Hasher().add("tfd").add(3.5).finish());
  const Hash h = Hasher().add("x").finish();
  EXPECT_EQ(h.toHex().size(), 32u);
  EXPECT_NE(outputHash(h, "a"), outputHash(h, "b"));
}

}  // namespace
}  // namespace tfd::graph
