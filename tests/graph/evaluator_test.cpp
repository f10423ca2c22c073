// Cooking: pull-based, cached by content hash, per-node errors, cancellation (in the spirit of
// Gaffer's ComputeNode tests, with the dummy node types of tests/support).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <set>

#include "graph/errors.h"
#include "graph/evaluator.h"
#include "graph/topology.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

using test::cookLog;
using test::Number;

class Evaluation : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    cookLog().clear();
  }

  /// c1(2), c2(3) --> add --> scale(x2) --> sink
  Graph chain() {
    Graph g(registry);
    g.addNode("Constant", "c1");
    g.setParam("c1", "value", 2.0);
    g.addNode("Constant", "c2");
    g.setParam("c2", "value", 3.0);
    g.addNode("Add", "add");
    g.addNode("Scale", "scale");
    g.addNode("Sink", "sink");
    g.connect({"c1", "out"}, {"add", "a"});
    g.connect({"c2", "out"}, {"add", "b"});
    g.connect({"add", "sum"}, {"scale", "in"});
    g.connect({"scale", "out"}, {"sink", "in"});
    return g;
  }

  std::set<std::string> cooked() {
    auto v = cookLog().nodes();
    return {v.begin(), v.end()};
  }

  NodeRegistry registry;
};

TEST_F(Evaluation, CooksInDependencyOrderAndComputesValues) {
  Evaluator ev;
  const CookResult r = ev.cook(chain());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(cookLog().sinks().at("sink"), 10.0);
  EXPECT_EQ(r.output<Number>("scale", "out")->value, 10.0);
  EXPECT_EQ(r.output<Number>("add", "sum")->value, 5.0);
  EXPECT_EQ(r.output<Number>("add", "nope"), nullptr);
  EXPECT_EQ(r.count(NodeState::Cooked), 5u);
  const auto order = cookLog().nodes();
  auto pos = [&](const std::string& n) {
    return std::find(order.begin(), order.end(), n) - order.begin();
  };
  EXPECT_LT(pos("c1"), pos("add"));
  EXPECT_LT(pos("c2"), pos("add"));
  EXPECT_LT(pos("add"), pos("scale"));
  EXPECT_LT(pos("scale"), pos("sink"));
  std::vector<std::string> reportOrder;
  for (const NodeReport& rep : r.reports) reportOrder.push_back(rep.node);
  EXPECT_EQ(reportOrder, (std::vector<std::string>{"c1", "c2", "add", "scale", "sink"}));
  for (const NodeReport& rep : r.reports) {
    EXPECT_TRUE(rep.cookCalled);
    EXPECT_GE(rep.seconds, 0.0);
    EXPECT_FALSE(rep.key.isZero());
  }
}

TEST_F(Evaluation, UnchangedRecookComputesNothing) {
  Evaluator ev;
  Graph g = chain();
  ev.cook(g);
  cookLog().clear();
  const CookResult again = ev.cook(g);
  EXPECT_EQ(cookLog().total(), 0);
  EXPECT_EQ(again.count(NodeState::Cached), 5u);
  EXPECT_TRUE(again.ok());
  EXPECT_EQ(again.output<Number>("scale", "out")->value, 10.0) << "cached outputs are returned";
  ASSERT_EQ(again.report("sink")->messages.size(), 1u) << "cached messages are kept";
  EXPECT_FALSE(again.report("sink")->cookCalled);
  // A copy of the graph (what an editor cooks in the background) hits the same cache.
  Graph copy = g;
  ev.cook(copy);
  EXPECT_EQ(cookLog().total(), 0);
}

TEST_F(Evaluation, ParameterChangeRecooksExactlyDownstream) {
  Evaluator ev;
  Graph g = chain();
  g.addNode("Constant", "other");  // an unrelated branch
  ev.cook(g);
  const std::vector<std::pair<std::string, std::string>> edits{
      {"c1", "value"}, {"c2", "value"}, {"add", "bias"}, {"scale", "factor"}};
  double value = 0.75;
  for (const auto& [node, param] : edits) {
    SCOPED_TRACE(node);
    cookLog().clear();
    g.setParam(node, param, value += 1);  // distinct: equal constants share one cache entry
    ev.cook(g);
    std::set<std::string> expected{node};
    for (const std::string& d : downstreamOf(g, node)) expected.insert(d);
    EXPECT_EQ(cooked(), expected);
    EXPECT_EQ(cookLog().total(), static_cast<int>(expected.size())) << "each cooked once";
  }
}

TEST_F(Evaluation, DirtyPropagationAndFreeUndo) {
  Evaluator ev;
  Graph g = chain();
  EXPECT_EQ(ev.dirtyNodes(g), (std::vector<std::string>{"c1", "c2", "add", "scale", "sink"}));
  ev.cook(g);
  EXPECT_TRUE(ev.dirtyNodes(g).empty());
  g.setParam("c2", "value", 4.0);
  EXPECT_EQ(ev.dirtyNodes(g), (std::vector<std::string>{"c2", "add", "scale", "sink"}));
  EXPECT_EQ(ev.dirtyNodes(g, {.targets = {"add"}}), (std::vector<std::string>{"c2", "add"}));
  ev.cook(g);
  EXPECT_TRUE(ev.dirtyNodes(g).empty());
  g.setParam("c2", "value", 3.0);  // undo: the old result is still cached
  EXPECT_TRUE(ev.dirtyNodes(g).empty());
  cookLog().clear();
  EXPECT_EQ(ev.cook(g).output<Number>("scale", "out")->value, 10.0);
  EXPECT_EQ(cookLog().total(), 0);
  // Editor data and node names are not part of the result.
  g.setUi("add", Json::parse(R"({"position": [1, 2]})"));
  g.renameNode("scale", "times_two");
  EXPECT_TRUE(ev.dirtyNodes(g).empty());
  // Relinking changes the key.
  g.disconnect({"c1", "out"}, {"add", "a"});
  g.disconnect({"c2", "out"}, {"add", "b"});
  g.connect({"c2", "out"}, {"add", "a"});
  g.connect({"c1", "out"}, {"add", "b"});
  EXPECT_EQ(ev.dirtyNodes(g), (std::vector<std::string>{"add", "times_two", "sink"}));
}

TEST_F(Evaluation, FailureIsContainedAndReportedDownstream) {
  Graph g(registry);
  g.addNode("Constant", "c1");
  g.addNode("Scale", "bad");
  g.setParam("bad", "fail", true);
  g.addNode("Scale", "after");
  g.addNode("Sink", "sink1");
  g.addNode("Constant", "c2");
  g.addNode("Sink", "sink2");
  g.connect({"c1", "out"}, {"bad", "in"});
  g.connect({"bad", "out"}, {"after", "in"});
  g.connect({"after", "out"}, {"sink1", "in"});
  g.connect({"c2", "out"}, {"sink2", "in"});
  Evaluator ev;
  const CookResult r = ev.cook(g);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.report("bad")->state, NodeState::Failed);
  ASSERT_EQ(r.report("bad")->messages.size(), 1u);
  EXPECT_EQ(r.report("bad")->messages[0],
            (NodeMessage{Severity::Error, "scale failed on purpose", MessageKind::CookFailed}));
  EXPECT_EQ(r.report("after")->state, NodeState::UpstreamFailed);
  EXPECT_EQ(r.report("after")->messages.at(0).text, "input 'in' failed upstream in node \"bad\"");
  EXPECT_EQ(r.report("sink1")->state, NodeState::UpstreamFailed);
  EXPECT_EQ(r.report("sink1")->messages.at(0).text, "input 'in' failed upstream in node \"bad\"")
      << "the root failure is named, not the intermediate node";
  EXPECT_EQ(r.report("sink1")->failedNode, "bad");
  EXPECT_EQ(r.report("sink2")->state, NodeState::Cooked) << "the unrelated branch still cooks";
  EXPECT_EQ(r.report("c1")->state, NodeState::Cooked);
  EXPECT_EQ(cookLog().sinks().count("sink2"), 1u);
  EXPECT_EQ(cookLog().count("after"), 0);
  // Failures are not cached: fixing the parameter cooks the failed part only.
  g.setParam("bad", "fail", false);
  cookLog().clear();
  EXPECT_TRUE(ev.cook(g).ok());
  EXPECT_EQ(cooked(), (std::set<std::string>{"bad", "after", "sink1"}));
}

TEST_F(Evaluation, MissingRequiredInputUnsetOutputAndForeignExceptions) {
  NodeRegistry r;
  test::registerTestNodes(r);
  r.add(
      "ThrowsInt", 1, [](NodeDecl& d) { d.output<Number>("out"); }, [](CookContext&) { throw 42; });
  Graph g(r);
  g.addNode("Add", "add");
  g.addNode("Constant", "c");
  g.connect({"c", "out"}, {"add", "a"});
  g.addNode("Lazy", "lazy");
  g.connect({"c", "out"}, {"lazy", "in"});
  g.addNode("ThrowsInt", "weird");
  g.addNode("Sum", "empty_sum");  // an optional multiple input may stay unconnected
  Evaluator ev;
  const CookResult res = ev.cook(g);
  EXPECT_EQ(res.report("add")->state, NodeState::Failed);
  EXPECT_EQ(res.report("add")->messages.at(0).text, "required input 'b' is not connected");
  EXPECT_FALSE(res.report("add")->cookCalled);
  EXPECT_EQ(res.report("lazy")->messages.at(0).text, "output 'out' was not set by the node");
  EXPECT_NE(res.report("weird")->messages.at(0).text.find("unknown exception"), std::string::npos);
  EXPECT_EQ(res.report("empty_sum")->state, NodeState::Cooked);
  EXPECT_EQ(res.output<Number>("empty_sum", "out")->value, 0.0);
  EXPECT_EQ(res.report("empty_sum")->messages.at(0), (NodeMessage{Severity::Info, "0 values"}));
}

TEST_F(Evaluation, MultipleInputKeepsLinkOrder) {
  Graph g(registry);
  for (int i = 1; i <= 3; ++i) {
    g.addNode("Constant", "c" + std::to_string(i));
    g.setParam("c" + std::to_string(i), "value", double(i));
  }
  g.addNode("Sum", "sum");
  g.connect({"c2", "out"}, {"sum", "values"});
  g.connect({"c1", "out"}, {"sum", "values"});
  g.connect({"c3", "out"}, {"sum", "values"});
  Evaluator ev;
  EXPECT_EQ(ev.cook(g).output<Number>("sum", "out")->value, 2 + 10 * 1 + 100 * 3);
  g.disconnect({"c2", "out"}, {"sum", "values"});
  g.connect({"c2", "out"}, {"sum", "values"});
  EXPECT_EQ(ev.cook(g).output<Number>("sum", "out")->value, 1 + 10 * 3 + 100 * 2);
}

TEST_F(Evaluation, TargetsSelectWhatCooksAndLeavesAreTheDefault) {
  Graph g = chain();
  g.addNode("Constant", "dangling");
  Evaluator ev;
  const CookResult one = ev.cook(g, {.targets = {"add"}});
  EXPECT_EQ(cooked(), (std::set<std::string>{"c1", "c2", "add"}));
  EXPECT_EQ(one.reports.size(), 3u);
  EXPECT_EQ(one.report("sink"), nullptr);
  cookLog().clear();
  const CookResult all = ev.cook(g);
  EXPECT_EQ(cooked(), (std::set<std::string>{"scale", "sink", "dangling"}));
  EXPECT_EQ(all.reports.size(), 6u);
  EXPECT_THROW(ev.cook(g, {.targets = {"nope"}}), GraphError);
}

TEST_F(Evaluation, WarningsAndObserverEvents) {
  struct Recorder : CookObserver {
    std::mutex m;
    std::vector<std::string> events;
    std::size_t requested = 0, cached = 0;
    int progress = 0;
    void cookStarted(std::size_t r, std::size_t c) override { requested = r, cached = c; }
    void nodeStarted(const std::string& n, const std::string& t) override {
      std::lock_guard l(m);
      events.push_back("start " + n + " " + t);
    }
    void nodeProgress(const std::string& n, double f, std::string_view) override {
      std::lock_guard l(m);
      EXPECT_EQ(n, "wait");
      EXPECT_GE(f, 0.0);
      ++progress;
    }
    void nodeFinished(const NodeReport& r) override {
      std::lock_guard l(m);
      events.push_back("finish " + r.node + " " + std::string(stateName(r.state)));
    }
  };
  Graph g(registry);
  g.addNode("Wait", "wait");
  g.addNode("Scale", "warn");
  g.setParam("warn", "warn", true);
  g.connect({"wait", "out"}, {"warn", "in"});
  Evaluator ev;
  Recorder rec;
  const CookResult r = ev.cook(g, {.observer = &rec});
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.hasWarnings());
  EXPECT_EQ(r.report("warn")->messages.at(0),
            (NodeMessage{Severity::Warning, "scaled with a warning"}));
  EXPECT_EQ(rec.requested, 2u);
  EXPECT_EQ(rec.cached, 0u);
  EXPECT_GT(rec.progress, 0);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"start wait Wait", "finish wait cooked",
                                                  "start warn Scale", "finish warn cooked"}));
  Recorder again;
  ev.cook(g, {.observer = &again});
  EXPECT_EQ(again.cached, 2u);
  EXPECT_EQ(again.events, (std::vector<std::string>{"finish wait cached", "finish warn cached"}));
}

class CancelOnStart : public CookObserver {
 public:
  CancelOnStart(std::string node, std::atomic<bool>& flag) : node_(std::move(node)), flag_(flag) {}
  void nodeStarted(const std::string& n, const std::string&) override {
    if (n == node_) flag_ = true;
  }

 private:
  std::string node_;
  std::atomic<bool>& flag_;
};

TEST_F(Evaluation, CancellationLeavesNoPartialResultInTheCache) {
  for (bool ignoreCancel : {false, true}) {
    SCOPED_TRACE(ignoreCancel ? "node ignores the flag" : "node throws Cancelled");
    cookLog().clear();
    Graph g(registry);
    g.addNode("Constant", "c");
    g.addNode("Wait", "slow");
    g.setParam("slow", "seconds", 0.2);
    g.setParam("slow", "ignore_cancel", ignoreCancel);
    g.addNode("Scale", "after");
    g.addNode("Sink", "sink");
    g.connect({"c", "out"}, {"slow", "in"});
    g.connect({"slow", "out"}, {"after", "in"});
    g.connect({"after", "out"}, {"sink", "in"});
    Evaluator ev;
    std::atomic<bool> cancel{false};
    CancelOnStart observer("slow", cancel);
    const CookResult r = ev.cook(g, {.cancel = &cancel, .observer = &observer});
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.report("c")->state, NodeState::Cooked);
    EXPECT_EQ(r.report("slow")->state, NodeState::Cancelled);
    EXPECT_EQ(r.report("after")->state, NodeState::Cancelled);
    EXPECT_EQ(r.report("sink")->state, NodeState::Cancelled);
    EXPECT_EQ(r.output<Number>("slow", "out"), nullptr);
    EXPECT_EQ(cookLog().count("after"), 0);
    EXPECT_EQ(ev.cache().size(), 1u) << "only the completed constant is cached";
    EXPECT_TRUE(ev.cache().contains(r.report("c")->key));
    EXPECT_FALSE(ev.cache().contains(r.report("slow")->key));
    // Re-cooking without cancelling computes what was interrupted, not what completed.
    cookLog().clear();
    const CookResult again = ev.cook(g);
    EXPECT_TRUE(again.ok());
    EXPECT_EQ(cooked(), (std::set<std::string>{"slow", "after", "sink"}));
    EXPECT_EQ(again.report("c")->state, NodeState::Cached);
  }
}

TEST_F(Evaluation, CancelledBeforeStartCooksNothing) {
  Evaluator ev;
  std::atomic<bool> cancel{true};
  const CookResult r = ev.cook(chain(), {.cancel = &cancel});
  EXPECT_EQ(cookLog().total(), 0);
  EXPECT_EQ(r.count(NodeState::Cancelled), 5u);
  EXPECT_EQ(ev.cache().size(), 0u);
}

TEST_F(Evaluation, FilePathsResolveAndInputFilesFeedTheKey) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("tfd_eval_" + std::to_string(::getpid()));
  fs::create_directories(dir / "data");
  { std::ofstream(dir / "data" / "in.txt") << "hello"; }
  Graph g(registry);
  g.setSourcePath(dir / "g.tfd.json");
  g.addNode("ReadText", "read");
  g.setParam("read", "path", std::string("data/in.txt"));
  g.addNode("Constant", "c");
  g.addNode("Sink", "sink");
  g.connect({"c", "out"}, {"sink", "in"});
  Evaluator ev;
  CookResult r = ev.cook(g, {.outDir = dir / "out"});
  ASSERT_TRUE(r.ok()) << r.report("read")->messages.at(0).text;
  EXPECT_EQ(r.output<test::Text>("read", "out")->value, "hello");
  EXPECT_EQ(r.report("sink")->messages.at(0).text, "wrote " + (dir / "out" / "out.txt").string());
  // Without --out, outputs go next to the graph file.
  r = ev.cook(g);
  EXPECT_EQ(r.report("sink")->messages.at(0).text, "wrote " + (dir / "out.txt").string());
  // Editing the input file re-cooks its reader, and only that.
  { std::ofstream(dir / "data" / "in.txt") << "hello, world"; }
  cookLog().clear();
  r = ev.cook(g);
  EXPECT_EQ(cooked(), (std::set<std::string>{"read"}));
  EXPECT_EQ(r.output<test::Text>("read", "out")->value, "hello, world");
  // A missing input file is the node's error, naming the parameter.
  fs::remove(dir / "data" / "in.txt");
  r = ev.cook(g);
  EXPECT_EQ(r.report("read")->state, NodeState::Failed);
  EXPECT_EQ(r.report("read")->messages.at(0).text,
            "parameter 'path': cannot open " + (dir / "data" / "in.txt").string());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tfd::graph
