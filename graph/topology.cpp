#include "graph/topology.h"

#include <queue>
#include <set>

#include "graph/errors.h"

namespace tfd::graph {

std::vector<std::vector<int>> upstreamNodes(const Graph& graph) {
  std::vector<std::set<int>> sets(graph.nodeCount());
  for (const Link& l : graph.links()) {
    int from = graph.nodeIndex(l.from.node), to = graph.nodeIndex(l.to.node);
    if (from >= 0 && to >= 0) sets[to].insert(from);
  }
  std::vector<std::vector<int>> out(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i) out[i].assign(sets[i].begin(), sets[i].end());
  return out;
}

std::vector<int> topologicalOrder(const Graph& graph) {
  const auto upstream = upstreamNodes(graph);
  const int n = static_cast<int>(graph.nodeCount());
  std::vector<int> pending(n, 0);
  std::vector<std::vector<int>> downstream(n);
  for (int i = 0; i < n; ++i) {
    pending[i] = static_cast<int>(upstream[i].size());
    for (int u : upstream[i]) downstream[u].push_back(i);
  }
  std::priority_queue<int, std::vector<int>, std::greater<>> ready;
  for (int i = 0; i < n; ++i)
    if (pending[i] == 0) ready.push(i);
  std::vector<int> order;
  while (!ready.empty()) {
    int i = ready.top();
    ready.pop();
    order.push_back(i);
    for (int d : downstream[i])
      if (--pending[d] == 0) ready.push(d);
  }
  if (static_cast<int>(order.size()) != n) {
    std::string names;
    for (int i = 0; i < n; ++i)
      if (pending[i] > 0) names += (names.empty() ? "" : ", ") + graph.nodes()[i].name();
    throw GraphError("the graph contains a cycle through: " + names);
  }
  return order;
}

std::vector<std::vector<std::vector<Link>>> incomingLinks(const Graph& graph) {
  std::vector<std::vector<std::vector<Link>>> out(graph.nodeCount());
  for (std::size_t i = 0; i < graph.nodeCount(); ++i)
    out[i].resize(graph.nodes()[i].decl().inputs().size());
  for (const Link& l : graph.links()) {
    const int to = graph.nodeIndex(l.to.node);
    if (to < 0) continue;
    const int port = graph.nodes()[to].decl().inputIndex(l.to.port);
    if (port >= 0) out[to][port].push_back(l);
  }
  return out;
}

std::vector<bool> upstreamClosure(const Graph& graph, const std::vector<int>& targets) {
  const auto upstream = upstreamNodes(graph);
  std::vector<bool> marked(graph.nodeCount(), false);
  std::vector<int> stack(targets.begin(), targets.end());
  while (!stack.empty()) {
    int i = stack.back();
    stack.pop_back();
    if (marked[i]) continue;
    marked[i] = true;
    for (int u : upstream[i]) stack.push_back(u);
  }
  return marked;
}

std::vector<std::string> downstreamOf(const Graph& graph, std::string_view node) {
  const int n = static_cast<int>(graph.nodeCount());
  std::vector<bool> marked(n, false);
  std::vector<std::string> stack{std::string(node)};
  while (!stack.empty()) {
    std::string current = stack.back();
    stack.pop_back();
    for (const Link& l : graph.links()) {
      if (l.from.node != current) continue;
      int i = graph.nodeIndex(l.to.node);
      if (i >= 0 && !marked[i]) {
        marked[i] = true;
        stack.push_back(l.to.node);
      }
    }
  }
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i)
    if (marked[i]) out.push_back(graph.nodes()[i].name());
  return out;
}

std::vector<int> leafNodes(const Graph& graph) {
  std::vector<bool> feeds(graph.nodeCount(), false);
  for (const Link& l : graph.links())
    if (int i = graph.nodeIndex(l.from.node); i >= 0) feeds[i] = true;
  std::vector<int> out;
  for (std::size_t i = 0; i < feeds.size(); ++i)
    if (!feeds[i]) out.push_back(static_cast<int>(i));
  return out;
}

}  // namespace tfd::graph
