// Message kinds: an upstream failure is its own kind naming the input port and the failing node
// (no text matching needed), in port order then link order; and the whole report (states,
// messages, their order) is identical for 1 and 2 threads and for sequential cooking.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>

#include "graph/evaluator.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

class Messages : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    test::cookLog().clear();
  }
  NodeRegistry registry;
};

void addFailing(Graph& g, const std::string& name) {
  g.addNode("Scale", name);
  g.setParam(name, "fail", true);
  g.connect({"c", "out"}, {name, "in"});
}

TEST_F(Messages, UpstreamFailuresAreTheirOwnKindNamingPortAndFailingNode) {
  Graph g(registry);
  g.addNode("Constant", "c");
  addFailing(g, "f1");
  addFailing(g, "f2");
  addFailing(g, "f3");
  g.addNode("Scale", "mid");  // fails upstream because of f1
  g.connect({"f1", "out"}, {"mid", "in"});
  g.addNode("Sum", "sum");  // links in this order: f3, mid (root f1), f1 (again f1), c
  g.connect({"f3", "out"}, {"sum", "values"});
  g.connect({"mid", "out"}, {"sum", "values"});
  g.connect({"f1", "out"}, {"sum", "values"});
  g.connect({"c", "out"}, {"sum", "values"});
  g.addNode("Add", "add");  // a from f2, b from f1: port order
  g.connect({"f2", "out"}, {"add", "a"});
  g.connect({"f1", "out"}, {"add", "b"});
  g.addNode("Add", "half");  // b unconnected, a failed upstream: the upstream failure wins
  g.connect({"f3", "out"}, {"half", "a"});
  g.addNode("Add", "lonely");  // nothing connected: two missing inputs
  Evaluator ev;
  const CookResult r = ev.cook(g);

  const NodeMessage& own = r.report("f1")->messages.at(0);
  EXPECT_EQ(own.kind, MessageKind::CookFailed);
  EXPECT_EQ(own.severity, Severity::Error);
  EXPECT_TRUE(own.port.empty() && own.sourceNode.empty());

  const NodeReport& mid = *r.report("mid");
  EXPECT_EQ(mid.state, NodeState::UpstreamFailed);
  ASSERT_EQ(mid.messages.size(), 1u);
  EXPECT_EQ(mid.messages[0], upstreamFailedMessage("in", "f1"));
  EXPECT_EQ(mid.messages[0].kind, MessageKind::UpstreamFailed);
  EXPECT_EQ(mid.messages[0].port, "in");
  EXPECT_EQ(mid.messages[0].sourceNode, "f1");
  EXPECT_EQ(mid.messages[0].text, "input 'in' failed upstream in node \"f1\"");

  const NodeReport& sum = *r.report("sum");
  EXPECT_EQ(sum.state, NodeState::UpstreamFailed);
  EXPECT_EQ(sum.failedNode, "f3");
  EXPECT_EQ(sum.messages, (std::vector<NodeMessage>{upstreamFailedMessage("values", "f3"),
                                                    upstreamFailedMessage("values", "f1")}))
      << "link order; one message per failing root node";

  EXPECT_EQ(r.report("add")->messages, (std::vector<NodeMessage>{upstreamFailedMessage("a", "f2"),
                                                                 upstreamFailedMessage("b", "f1")}))
      << "port order, not the text's alphabetical order";
  EXPECT_EQ(r.report("half")->state, NodeState::UpstreamFailed);
  EXPECT_EQ(r.report("half")->messages,
            (std::vector<NodeMessage>{upstreamFailedMessage("a", "f3")}));

  const NodeReport& lonely = *r.report("lonely");
  EXPECT_EQ(lonely.state, NodeState::Failed);
  EXPECT_EQ(lonely.messages,
            (std::vector<NodeMessage>{missingInputMessage("a"), missingInputMessage("b")}));
  EXPECT_EQ(lonely.messages[1].kind, MessageKind::MissingInput);
  EXPECT_EQ(lonely.messages[1].port, "b");
  EXPECT_EQ(messageKindName(MessageKind::UpstreamFailed), "upstream failed");
}

TEST_F(Messages, TheOwnMessagesOfANodeHaveKindReportedAndUnsetOutputsNameTheirPort) {
  Graph g(registry);
  g.addNode("Constant", "c");
  g.addNode("Scale", "warn");
  g.setParam("warn", "warn", true);
  g.connect({"c", "out"}, {"warn", "in"});
  g.addNode("Lazy", "lazy");
  g.connect({"c", "out"}, {"lazy", "in"});
  Evaluator ev;
  const CookResult r = ev.cook(g);
  EXPECT_EQ(r.report("warn")->messages.at(0).kind, MessageKind::Reported);
  EXPECT_EQ(r.report("warn")->messages.at(0).severity, Severity::Warning);
  const NodeMessage& unset = r.report("lazy")->messages.at(0);
  EXPECT_EQ(unset.kind, MessageKind::OutputNotSet);
  EXPECT_EQ(unset.port, "out");
  // A cached node keeps its messages, kinds included.
  const CookResult again = ev.cook(g);
  EXPECT_EQ(again.report("warn")->state, NodeState::Cached);
  EXPECT_EQ(again.report("warn")->messages, r.report("warn")->messages);
}

/// 16 constants, each through a Scale (every third fails, every other warns), pairs of Scales
/// added, and every Add summed in reverse order into a sink.
Graph failingWideGraph(const NodeRegistry& registry) {
  Graph g(registry);
  const int n = 16;
  for (int i = 0; i < n; ++i) {
    const std::string c = "c" + std::to_string(i), s = "s" + std::to_string(i);
    g.addNode("Constant", c);
    g.setParam(c, "value", 1.0 + i);
    g.addNode("Scale", s);
    g.setParam(s, "fail", i % 3 == 1);
    g.setParam(s, "warn", i % 2 == 0);
    g.connect({c, "out"}, {s, "in"});
  }
  for (int i = 0; i < n; ++i) {
    const std::string a = "add" + std::to_string(i);
    g.addNode("Add", a);
    g.connect({"s" + std::to_string(i), "out"}, {a, "a"});
    g.connect({"s" + std::to_string((i * 5 + 3) % n), "out"}, {a, "b"});
  }
  g.addNode("Sum", "total");
  for (int i = n - 1; i >= 0; --i)
    g.connect({"add" + std::to_string(i), "sum"}, {"total", "values"});
  g.addNode("Sink", "sink");
  g.connect({"total", "out"}, {"sink", "in"});
  return g;
}

struct Digest {
  std::string node;
  NodeState state;
  std::string failedNode;
  std::vector<NodeMessage> messages;
  bool operator==(const Digest&) const = default;
};

std::vector<Digest> digest(const CookResult& r) {
  std::vector<Digest> out;
  for (const NodeReport& rep : r.reports)
    out.push_back({rep.node, rep.state, rep.failedNode, rep.messages});
  return out;
}

TEST_F(Messages, TheReportIsIdenticalForOneAndTwoThreadsAndSequentialCooking) {
  const Graph g = failingWideGraph(registry);
  std::vector<std::vector<Digest>> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    for (bool parallel : {true, false})
      for (int repeat = 0; repeat < 3; ++repeat) {
        Evaluator ev;
        runs.push_back(digest(ev.cook(g, {.parallel = parallel})));
      }
  }
  ASSERT_EQ(runs[0].size(), 50u);
  std::size_t upstream = 0;
  for (const Digest& d : runs[0]) upstream += d.state == NodeState::UpstreamFailed;
  EXPECT_GT(upstream, 5u);
  const auto total = std::find_if(runs[0].begin(), runs[0].end(),
                                  [](const Digest& d) { return d.node == "total"; });
  ASSERT_NE(total, runs[0].end());
  EXPECT_GT(total->messages.size(), 2u) << "the sum hears of several failures";
  for (std::size_t i = 1; i < runs.size(); ++i) EXPECT_EQ(runs[i], runs[0]) << "run " << i;
}

}  // namespace
}  // namespace tfd::graph
