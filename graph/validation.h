#pragma once
// Checks beyond what a Graph guarantees by construction, for `tfd validate` and an editor's
// problem list: required inputs without a link (error) and input files that do not exist
// (warning).
#include <string>
#include <vector>

#include "graph/graph.h"
#include "graph/node_message.h"
#include "graph/paths.h"

namespace tfd::graph {

struct Issue {
  Severity severity = Severity::Error;
  std::string node;     ///< the node concerned
  std::string pointer;  ///< JSON pointer of the place in the graph file
  std::string message;
};

/// In node order, then port/parameter declaration order.
std::vector<Issue> validateGraph(const Graph& graph, const PathContext& paths);

}  // namespace tfd::graph
