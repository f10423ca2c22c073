// Overhead of the graph engine itself (hashing, scheduling, caching) with trivial nodes, so
// that real graphs' cook times are dominated by their algorithms. Run:
//   build/bench/graph_engine_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "graph/evaluator.h"
#include "graph/node_keys.h"

namespace {
struct BenchNumber {
  double value = 0;
};
}  // namespace
TFD_GRAPH_VALUE_TYPE(BenchNumber, "BenchNumber");

namespace {

using namespace tfd::graph;

void registerBenchNodes(NodeRegistry& r) {
  r.add(
      "BConst", 1,
      [](NodeDecl& d) {
        d.output<BenchNumber>("out");
        d.param<double>("value");
        d.param<std::string>("label").byDefault("constant");
        d.param<Vec3Param>("position");
      },
      [](CookContext& c) {
        c.setOutput("out",
                    std::make_shared<const BenchNumber>(BenchNumber{c.param<double>("value")}));
      });
  r.add(
      "BAdd", 1,
      [](NodeDecl& d) {
        d.input<BenchNumber>("a");
        d.input<BenchNumber>("b");
        d.output<BenchNumber>("sum");
        d.param<double>("bias");
      },
      [](CookContext& c) {
        c.setOutput("sum", std::make_shared<const BenchNumber>(BenchNumber{
                               c.input<BenchNumber>("a")->value + c.input<BenchNumber>("b")->value +
                               c.param<double>("bias")}));
      });
}

/// A binary reduction tree over n constants: n constants + n-1 adders.
Graph tree(const NodeRegistry& registry, int n) {
  Graph g(registry);
  std::vector<std::string> layer;
  for (int i = 0; i < n; ++i) {
    layer.push_back(std::string("c") + std::to_string(i));
    g.addNode("BConst", layer.back());
    g.setParam(layer.back(), "value", double(i));
  }
  int id = 0;
  while (layer.size() > 1) {
    std::vector<std::string> next;
    for (std::size_t i = 0; i + 1 < layer.size(); i += 2) {
      const std::string add = "add" + std::to_string(id++);
      g.addNode("BAdd", add);
      g.connect({layer[i], layer[i][0] == 'c' ? "out" : "sum"}, {add, "a"});
      g.connect({layer[i + 1], layer[i + 1][0] == 'c' ? "out" : "sum"}, {add, "b"});
      next.push_back(add);
    }
    if (layer.size() % 2) next.push_back(layer.back());
    layer = next;
  }
  return g;
}

void BM_CookFresh(benchmark::State& state) {
  NodeRegistry registry;
  registerBenchNodes(registry);
  const Graph g = tree(registry, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Evaluator ev;
    benchmark::DoNotOptimize(ev.cook(g));
  }
  state.counters["nodes"] = static_cast<double>(g.nodeCount());
  state.counters["nodes_per_s"] = benchmark::Counter(static_cast<double>(g.nodeCount()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CookFresh)->Arg(64)->Arg(512)->Unit(benchmark::kMillisecond);

void BM_CookCached(benchmark::State& state) {
  NodeRegistry registry;
  registerBenchNodes(registry);
  const Graph g = tree(registry, static_cast<int>(state.range(0)));
  Evaluator ev;
  ev.cook(g);
  for (auto _ : state) benchmark::DoNotOptimize(ev.cook(g));
  state.counters["nodes"] = static_cast<double>(g.nodeCount());
}
BENCHMARK(BM_CookCached)->Arg(64)->Arg(512)->Unit(benchmark::kMillisecond);

void BM_NodeKeys(benchmark::State& state) {
  NodeRegistry registry;
  registerBenchNodes(registry);
  const Graph g = tree(registry, static_cast<int>(state.range(0)));
  const KeyOptions options{makePathContext(g), true};
  for (auto _ : state) benchmark::DoNotOptimize(computeNodeKeys(g, options));
  state.counters["nodes"] = static_cast<double>(g.nodeCount());
}
BENCHMARK(BM_NodeKeys)->Arg(64)->Arg(512)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
