#pragma once
// The three phases of Evaluator::cook (internal to the graph layer):
//
//   gather  single-threaded: the requested closure, every node's key, the cache hits (a
//           side-effect node counts as a hit only while the files it wrote are unchanged),
//           and for the nodes to cook their dependencies among each other.
//   run     cooks the nodes to cook, each as soon as the nodes it depends on are done,
//           independent ones in parallel; fills their reports (state, messages, outputs, files).
//   store   inserts the cooked results into the cache in topological order and moves the
//           requested reports, in topological order, into the CookResult.
#include <cstddef>
#include <vector>

#include "graph/evaluator.h"
#include "graph/paths.h"

namespace tfd::graph {

struct CookPlan {
  const Graph* graph = nullptr;
  PathContext paths;
  std::vector<int> order;                                ///< every node, topological
  std::vector<bool> needed;                              ///< in the requested closure
  std::vector<Hash> keys;                                ///< per node
  std::vector<std::vector<std::vector<Link>>> incoming;  ///< per node, per input port
  std::vector<NodeReport> reports;                       ///< per node (needed ones filled)
  std::vector<bool> toCook;                              ///< needed and not a valid cache hit
  std::vector<bool> diskPending;                         ///< cached on disk, values not read yet
  std::vector<int> waitingOn;  ///< per node to cook: how many nodes to cook it depends on
  std::vector<std::vector<int>> dependents;  ///< per node to cook: nodes to cook that need it
  std::size_t requested = 0, cached = 0;
};

/// The requested nodes' indices (default: the leaves). Throws GraphError for an unknown name.
std::vector<int> targetIndices(const Graph& graph, const std::vector<std::string>& targets);

/// A cache entry that may stand for this cook of a node: present and, for a side-effect node,
/// with its written files unchanged on disk. `stale` tells whether an entry was rejected.
bool validCacheEntry(const CacheEntry* entry, const NodeDecl& decl, bool* stale = nullptr);

CookPlan gatherCook(const Graph& graph, const CookOptions& options, ValueCache& cache);
void runCook(CookPlan& plan, const CookOptions& options);
CookResult storeCook(CookPlan& plan, const CookOptions& options, ValueCache& cache);

/// Cooks node i of the plan (its upstream is done): inputs, the node's cook, outputs, files.
/// Fills plan.reports[i]; called from worker threads, one per node.
void cookNode(CookPlan& plan, int i, const CookOptions& options);

}  // namespace tfd::graph
