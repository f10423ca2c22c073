// The memory-bounded LRU cache of cooked results.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/value_cache.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

Hash key(int i) { return Hasher().add(i).finish(); }

CacheEntry blobEntry(std::size_t kb) {
  auto b = std::make_shared<const test::Blob>(test::Blob{std::vector<char>(kb * 1024)});
  return CacheEntry{{Value::of<test::Blob>(b)}, {}, 0, 0};
}

TEST(ValueCache, ValuesReportTheirSize) {
  const CacheEntry e = blobEntry(4);
  EXPECT_EQ(e.outputs[0].byteSize(), 4096u);
  auto n = std::make_shared<const test::Number>(test::Number{1});
  EXPECT_EQ(Value::of<test::Number>(n).byteSize(), sizeof(test::Number)) << "default: sizeof";
  EXPECT_EQ(ValueCache::entryBytes(e), 4096u + 128u);
}

TEST(ValueCache, EvictsLeastRecentlyUsedBeyondBudget) {
  const std::size_t entry = ValueCache::entryBytes(blobEntry(10));
  ValueCache cache(3 * entry + entry / 2);
  for (int i = 0; i < 3; ++i) cache.insert(key(i), blobEntry(10));
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(cache.bytes(), 3 * entry);
  ASSERT_NE(cache.find(key(0)), nullptr);  // 0 becomes most recently used; 1 is now oldest
  cache.insert(key(3), blobEntry(10));
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_FALSE(cache.contains(key(1)));
  EXPECT_TRUE(cache.contains(key(0)));
  EXPECT_TRUE(cache.contains(key(2)));
  EXPECT_TRUE(cache.contains(key(3)));
  EXPECT_EQ(cache.evictions(), 1u);
  EXPECT_LE(cache.bytes(), cache.budget());
  // A value still in use survives eviction of its entry.
  auto held = cache.find(key(2));
  cache.setBudget(entry);
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_TRUE(cache.contains(key(2))) << "most recently used kept";
  cache.setBudget(entry / 2);
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(held->outputs[0].as<test::Blob>()->bytes.size(), 10u * 1024);
  // An entry larger than the whole budget is not kept.
  cache.insert(key(9), blobEntry(100));
  EXPECT_FALSE(cache.contains(key(9)));
  EXPECT_EQ(cache.bytes(), 0u);
  // Replacing an entry does not double count.
  cache.setBudget(1 << 30);
  cache.insert(key(5), blobEntry(1));
  cache.insert(key(5), blobEntry(2));
  EXPECT_EQ(cache.bytes(), ValueCache::entryBytes(blobEntry(2)));
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.bytes(), 0u);
}

TEST(ValueCache, EvaluatorStaysWithinBudgetAndRecooksEvictedNodes) {
  NodeRegistry registry;
  test::registerTestNodes(registry);
  test::cookLog().clear();
  Graph g(registry);
  for (int i = 0; i < 4; ++i) {
    const std::string n = "blob" + std::to_string(i);
    g.addNode("Blob", n);
    g.setParam(n, "kilobytes", std::int64_t{64});
    g.setParam(n, "seed", std::int64_t{i});
  }
  const std::size_t entry = ValueCache::entryBytes(blobEntry(64));
  Evaluator ev(2 * entry + 1000);  // room for two of the four results
  CookResult r = ev.cook(g, {.parallel = false});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.output<test::Blob>("blob3", "out")->bytes.size(), 64u * 1024)
      << "the result of this cook holds every value even when the cache could not";
  EXPECT_EQ(ev.cache().size(), 2u);
  EXPECT_LE(ev.cache().bytes(), ev.cache().budget());
  EXPECT_EQ(ev.cache().evictions(), 2u);
  // blob2 and blob3 stayed; cooking blob0 and blob1 again evicts them in turn.
  test::cookLog().clear();
  ev.cook(g, {.parallel = false});
  EXPECT_EQ(test::cookLog().count("blob0"), 1);
  EXPECT_EQ(test::cookLog().count("blob1"), 1);
  EXPECT_EQ(test::cookLog().count("blob2") + test::cookLog().count("blob3"), 0);
}

}  // namespace
}  // namespace tfd::graph
