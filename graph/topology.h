#pragma once
// Order and reachability over a Graph's links (node indices refer to Graph::nodes()).
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"

namespace tfd::graph {

/// Every node, upstream before downstream; among independent nodes, file order. Deterministic.
/// Throws GraphError naming a cycle if the links contain one (Graph::connect prevents that).
std::vector<int> topologicalOrder(const Graph& graph);

/// For each node, the indices of the distinct nodes linked into it (ascending).
std::vector<std::vector<int>> upstreamNodes(const Graph& graph);

/// For each node, for each of its input ports (declaration order), the links into it in link
/// order. One pass over the links: use it instead of Graph::linksInto in loops over all nodes.
std::vector<std::vector<std::vector<Link>>> incomingLinks(const Graph& graph);

/// Marks `targets` and everything upstream of them.
std::vector<bool> upstreamClosure(const Graph& graph, const std::vector<int>& targets);

/// Names of the nodes downstream of `node` (not including it), in file order.
std::vector<std::string> downstreamOf(const Graph& graph, std::string_view node);

/// Nodes whose outputs feed no link (sinks and dangling results), in file order: what "cook the
/// whole graph" cooks.
std::vector<int> leafNodes(const Graph& graph);

}  // namespace tfd::graph
