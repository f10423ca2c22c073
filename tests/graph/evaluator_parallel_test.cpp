// Independent branches cook concurrently; results do not depend on the thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "graph/evaluator.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

using test::Number;

class ParallelEvaluation : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    test::cookLog().clear();
    test::rendezvous().reset();
  }
  NodeRegistry registry;
};

Graph twoBranches(const NodeRegistry& registry, double timeout) {
  Graph g(registry);
  g.addNode("Rendezvous", "left");
  g.addNode("Rendezvous", "right");
  g.setParam("right", "value", 1.0);
  for (const char* n : {"left", "right"}) g.setParam(n, "timeout", timeout);
  g.addNode("Sum", "sum");
  g.connect({"left", "out"}, {"sum", "values"});
  g.connect({"right", "out"}, {"sum", "values"});
  return g;
}

TEST_F(ParallelEvaluation, IndependentBranchesCookConcurrently) {
  if (tbb::this_task_arena::max_concurrency() < 2) GTEST_SKIP() << "needs two threads";
  tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
  Evaluator ev;
  const CookResult r = ev.cook(twoBranches(registry, 10.0));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(test::rendezvous().peak.load(), 2) << "both branches were inside cook at once";
  EXPECT_LT(r.report("left")->seconds, 9.0) << "the rendezvous did not time out";
  EXPECT_EQ(r.output<Number>("sum", "out")->value, 10.0);
}

TEST_F(ParallelEvaluation, OneThreadOrSequentialCooksOneNodeAtATime) {
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    Evaluator ev;
    EXPECT_TRUE(ev.cook(twoBranches(registry, 0.05)).ok());
    EXPECT_EQ(test::rendezvous().peak.load(), 1);
  }
  test::rendezvous().reset();
  Evaluator ev;
  EXPECT_TRUE(ev.cook(twoBranches(registry, 0.05), {.parallel = false}).ok());
  EXPECT_EQ(test::rendezvous().peak.load(), 1);
}

/// A wide graph: 24 constants, then layers of Add / Scale / Sum with crossing links.
Graph wideGraph(const NodeRegistry& registry) {
  Graph g(registry);
  std::vector<std::string> layer;
  for (int i = 0; i < 24; ++i) {
    const std::string n = std::string("c") + std::to_string(i);
    g.addNode("Constant", n);
    g.setParam(n, "value", 0.1 * i + 1.0 / (i + 3));
    layer.push_back(n);
  }
  int id = 0;
  while (layer.size() > 1) {
    std::vector<std::string> next;
    for (std::size_t i = 0; i + 1 < layer.size(); i += 2) {
      const std::string add = "add" + std::to_string(id++);
      g.addNode("Add", add);
      g.setParam(add, "bias", 1e-3 * id);
      g.connect({layer[i], layer[i].starts_with("add") ? "sum" : "out"}, {add, "a"});
      g.connect({layer[(i + 3) % layer.size()],
                 layer[(i + 3) % layer.size()].starts_with("add") ? "sum" : "out"},
                {add, "b"});
      next.push_back(add);
    }
    layer = next;
  }
  g.addNode("Sum", "total");
  for (const Node& n : std::vector<Node>(g.nodes()))
    if (n.type().name() == "Add") g.connect({n.name(), "sum"}, {"total", "values"});
  g.addNode("Sink", "sink");
  g.connect({"total", "out"}, {"sink", "in"});
  return g;
}

std::vector<std::pair<std::string, double>> outputs(const CookResult& r) {
  std::vector<std::pair<std::string, double>> out;
  for (const NodeReport& rep : r.reports)
    if (!rep.outputs.empty()) out.emplace_back(rep.node, rep.outputs[0].as<Number>()->value);
  return out;
}

TEST_F(ParallelEvaluation, ResultsAreIdenticalForAnyThreadCount) {
  const Graph g = wideGraph(registry);
  std::vector<std::vector<std::pair<std::string, double>>> runs;
  std::vector<std::vector<Hash>> keys;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    for (bool parallel : {true, false}) {
      Evaluator ev;
      const CookResult r = ev.cook(g, {.parallel = parallel});
      ASSERT_TRUE(r.ok());
      runs.push_back(outputs(r));
      keys.emplace_back();
      for (const NodeReport& rep : r.reports) keys.back().push_back(rep.key);
    }
  }
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i], runs[0]) << "run " << i;  // bitwise: exact double equality
    EXPECT_EQ(keys[i], keys[0]);
  }
  EXPECT_GT(runs[0].size(), 40u);
}

}  // namespace
}  // namespace tfd::graph
