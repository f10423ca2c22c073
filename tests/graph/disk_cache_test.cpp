// The on-disk cook cache (graph/disk_cache.h) with the dummy node types: a fresh Evaluator
// (as a new process would) takes unchanged nodes from disk and reads values only where a
// node that cooks needs them; damaged entries (a flipped byte, a truncation, another format
// version) are misses with a warning and never change a result; the folder is trimmed to its
// size budget, least recently used first.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "graph/disk_cache.h"
#include "graph/evaluator.h"
#include "tests/support/graph_test_nodes.h"
#include "tests/support/temp_dir.h"

namespace tfd::graph {
namespace {

namespace fs = std::filesystem;
using test::cookLog;
using test::Number;

ValueCodecs testCodecs() {
  ValueCodecs codecs;
  codecs.add<Number>(
      [](const Number& n, ByteWriter& w) { w.f64(n.value); },
      [](ByteReader& r, DecodeMemo&) { return std::make_shared<const Number>(Number{r.f64()}); });
  codecs.add<test::Blob>([](const test::Blob& b, ByteWriter& w) { w.array(b.bytes); },
                         [](ByteReader& r, DecodeMemo&) {
                           return std::make_shared<const test::Blob>(test::Blob{r.array<char>()});
                         });
  return codecs;
}

class DiskCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    cookLog().clear();
  }

  /// c1(2), c2(3) --> add --> scale(x factor) --> sink
  Graph chain(double factor = 2) {
    Graph g(registry);
    g.addNode("Constant", "c1");
    g.setParam("c1", "value", 2.0);
    g.addNode("Constant", "c2");
    g.setParam("c2", "value", 3.0);
    g.addNode("Add", "add");
    g.addNode("Scale", "scale");
    g.setParam("scale", "factor", factor);
    g.addNode("Sink", "sink");
    g.connect({"c1", "out"}, {"add", "a"});
    g.connect({"c2", "out"}, {"add", "b"});
    g.connect({"add", "sum"}, {"scale", "in"});
    g.connect({"scale", "out"}, {"sink", "in"});
    return g;
  }

  /// A cook by a fresh Evaluator (an empty memory cache), as `tfd cook --cache` would do.
  CookResult cookFresh(const Graph& g, DiskCache& disk) {
    cookLog().clear();
    CookOptions options;
    options.diskCache = &disk;
    Evaluator ev;
    return ev.cook(g, options);
  }

  std::set<std::string> cooked() {
    auto v = cookLog().nodes();
    return {v.begin(), v.end()};
  }

  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir.path()))
      if (e.path().extension() == ".tfdc") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
  }

  NodeRegistry registry;
  ValueCodecs codecs = testCodecs();
  test::TempDir dir{"disk-cache"};
};

TEST_F(DiskCacheTest, ASecondProcessTakesUnchangedNodesFromDisk) {
  DiskCache disk(dir.path(), DiskCache::kDefaultBudget, codecs);
  ASSERT_TRUE(cookFresh(chain(), disk).ok());
  EXPECT_EQ(cooked(), (std::set<std::string>{"c1", "c2", "add", "scale", "sink"}));
  EXPECT_EQ(disk.counters().stores, 5u);
  EXPECT_EQ(cookLog().sinks().at("sink"), 10.0);

  // Same graph: nothing cooks; nothing needs a value, so no payload is read at all.
  const CookResult same = cookFresh(chain(), disk);
  ASSERT_TRUE(same.ok());
  EXPECT_TRUE(cooked().empty());
  for (const NodeReport& r : same.reports) {
    EXPECT_EQ(r.state, NodeState::Cached) << r.node;
    EXPECT_TRUE(r.fromDisk) << r.node;
  }
  EXPECT_EQ(disk.counters().loads, 0u);

  // A downstream parameter changed: only scale and sink cook; add's value is read from disk.
  const CookResult changed = cookFresh(chain(5), disk);
  ASSERT_TRUE(changed.ok());
  EXPECT_EQ(cooked(), (std::set<std::string>{"scale", "sink"}));
  EXPECT_EQ(cookLog().sinks().at("sink"), 25.0);
  EXPECT_TRUE(changed.report("add")->fromDisk);
  EXPECT_TRUE(changed.report("c1")->fromDisk);
  EXPECT_EQ(changed.output<Number>("add", "sum")->value, 5.0);
  EXPECT_EQ(disk.counters().loads, 1u) << "only add's value was needed";
  EXPECT_TRUE(disk.warnings().empty());
}

TEST_F(DiskCacheTest, DamagedEntriesAreMissesWithAWarningNeverWrongValues) {
  DiskCache disk(dir.path(), DiskCache::kDefaultBudget, codecs);
  ASSERT_TRUE(cookFresh(chain(), disk).ok());
  Evaluator probe;
  const Hash addKey = probe.cook(chain()).report("add")->key;
  const fs::path addEntry = disk.entryPath(addKey);
  ASSERT_TRUE(fs::exists(addEntry));
  const std::string original = [&] {
    std::ifstream in(addEntry, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  auto writeEntry = [&](const std::string& bytes) {
    std::ofstream(addEntry, std::ios::binary | std::ios::trunc) << bytes;
  };
  struct Damage {
    const char* what;
    std::string bytes;
  };
  std::vector<Damage> damages;
  std::string flipped = original;
  flipped[flipped.size() - 3] ^= 0x40;  // inside the payload: add's value
  damages.push_back({"a flipped payload byte", flipped});
  std::string flippedMeta = original;
  flippedMeta[70] ^= 0x01;  // inside the description
  damages.push_back({"a flipped description byte", flippedMeta});
  damages.push_back({"a truncation", original.substr(0, original.size() - 4)});
  damages.push_back({"a short header", original.substr(0, 20)});
  std::string version = original;
  version[8] = 99;
  damages.push_back({"another format version", version});
  std::string key = original;
  key[20] ^= 0x10;
  damages.push_back({"another key", key});

  double factor = 7;
  for (const Damage& d : damages) {
    SCOPED_TRACE(d.what);
    writeEntry(d.bytes);
    DiskCache fresh(dir.path(), DiskCache::kDefaultBudget, codecs);
    factor += 1;  // a new factor each time: scale cooks and needs add's value
    const CookResult r = cookFresh(chain(factor), fresh);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(cookLog().sinks().at("sink"), 5 * factor);
    EXPECT_EQ(r.output<Number>("add", "sum")->value, 5.0);
    EXPECT_EQ(cookLog().count("add"), 1) << "the damaged node is cooked again";
    EXPECT_EQ(cookLog().count("c1"), 0) << "its inputs' values still come from disk";
    ASSERT_EQ(fresh.warnings().size(), 1u);
    EXPECT_NE(fresh.warnings()[0].find(addEntry.string()), std::string::npos);
    EXPECT_NE(fresh.warnings()[0].find("damaged"), std::string::npos) << fresh.warnings()[0];
    EXPECT_EQ(fresh.counters().stores, 3u) << "add written again, and the new scale and sink";
  }
}

TEST_F(DiskCacheTest, TrimmedToItsBudgetLeastRecentlyUsedFirst) {
  // Blobs of 40 KB: entries of a little more; a budget of 100 KB keeps two of them.
  auto blob = [&](int kb) {
    Graph g(registry);
    g.addNode("Blob", "b");
    g.setParam("b", "kilobytes", kb);
    return g;
  };
  std::vector<fs::path> order;
  DiskCache disk(dir.path(), 100 * 1024, codecs);
  for (int kb : {40, 41, 42}) {
    ASSERT_TRUE(cookFresh(blob(kb), disk).ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // distinct modification times
  }
  std::vector<fs::path> left = entries();
  ASSERT_EQ(left.size(), 2u) << "the oldest (40 KB) entry was removed";
  std::uintmax_t total = 0;
  for (const fs::path& p : left) total += fs::file_size(p);
  EXPECT_LE(total, 100u * 1024u);
  EXPECT_EQ(disk.counters().evictions, 1u);

  // Reading the 41 KB entry makes it recent: the next new entry evicts the 42 KB one.
  EXPECT_TRUE(cookFresh(blob(41), disk).report("b")->fromDisk);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(cookFresh(blob(43), disk).ok());
  EXPECT_TRUE(cookFresh(blob(41), disk).report("b")->fromDisk);
  EXPECT_FALSE(cookFresh(blob(42), disk).report("b")->fromDisk) << "evicted, cooked again";
}

TEST_F(DiskCacheTest, NodesWithoutCodecsAreNotStored) {
  ValueCodecs none;
  DiskCache disk(dir.path(), DiskCache::kDefaultBudget, none);
  ASSERT_TRUE(cookFresh(chain(), disk).ok());
  EXPECT_EQ(disk.counters().stores, 1u) << "only the sink (no outputs) has nothing to encode";
  const CookResult again = cookFresh(chain(), disk);
  EXPECT_EQ(cooked(), (std::set<std::string>{"c1", "c2", "add", "scale"}));
  EXPECT_TRUE(again.report("sink")->fromDisk);
}

TEST(ByteStream, ReaderNeverReadsPastTheEnd) {
  ByteWriter w;
  w.u64(1000).str("abc");
  ByteReader r(w.bytes());
  EXPECT_THROW(r.array<double>(), GraphError) << "1000 doubles announced, 11 bytes left";
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);  // published FNV-1a 64 test vector
}

TEST(ByteStream, ChecksumSeesEveryBitFlipAndTheLength) {
  // 1000 bytes: 31 whole 32-byte blocks (four lanes) and an 8-byte tail.
  std::string bytes(1000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 131 + 7);
  const std::uint64_t sum = checksum64(bytes);
  EXPECT_EQ(checksum64(std::string(bytes)), sum);
  for (std::size_t bit = 0; bit < 8 * bytes.size(); ++bit) {
    std::string flipped = bytes;
    flipped[bit / 8] = char(flipped[bit / 8] ^ (1 << (bit % 8)));
    ASSERT_NE(checksum64(flipped), sum) << "bit " << bit;
  }
  // Two words of one lane changed together, a zero byte appended, lanes swapped.
  std::string two = bytes;
  two[0] = char(two[0] ^ 1);
  two[32] = char(two[32] ^ 1);
  EXPECT_NE(checksum64(two), sum);
  EXPECT_NE(checksum64(bytes + std::string(1, '\0')), sum);
  std::string swapped = bytes;
  std::swap_ranges(swapped.begin(), swapped.begin() + 8, swapped.begin() + 8);
  EXPECT_NE(checksum64(swapped), sum);
  EXPECT_NE(checksum64(""), checksum64(std::string(1, '\0')));
}

}  // namespace
}  // namespace tfd::graph
