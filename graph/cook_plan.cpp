// The gather and store phases of a cook (cook_phases.h).
#include "graph/cook_phases.h"

#include "graph/disk_cache.h"
#include "graph/node_keys.h"
#include "graph/topology.h"

namespace tfd::graph {

std::vector<int> targetIndices(const Graph& graph, const std::vector<std::string>& targets) {
  if (targets.empty()) return leafNodes(graph);
  std::vector<int> out;
  for (const std::string& name : targets) {
    (void)graph.node(name);  // throws GraphError for an unknown node
    out.push_back(graph.nodeIndex(name));
  }
  return out;
}

bool validCacheEntry(const CacheEntry* entry, const NodeDecl& decl, bool* stale) {
  if (stale) *stale = false;
  if (!entry) return false;
  if (!decl.hasSideEffects() || filesUnchanged(entry->files)) return true;
  if (stale) *stale = true;
  return false;
}

namespace {

/// A disk entry standing for node i (its description only): the report becomes Cached.
bool lookOnDisk(CookPlan& p, int i, const CookOptions& options) {
  if (!options.diskCache) return false;
  const NodeDecl& decl = p.graph->nodes()[i].decl();
  std::optional<CacheEntry> entry = options.diskCache->readMeta(p.keys[i], decl);
  NodeReport& r = p.reports[i];
  if (!entry || !validCacheEntry(&*entry, decl, &r.filesChanged)) return false;
  r.state = NodeState::Cached;
  r.fromDisk = true;
  r.messages = std::move(entry->messages);
  r.seconds = entry->seconds;
  r.files = std::move(entry->files);
  p.diskPending[i] = decl.outputs().size() > 0;
  ++p.cached;
  return true;
}

/// Reads the values of the disk hits that nodes to cook need; a hit that cannot be read is
/// cooked instead (reverse topological order, so its own inputs are considered after it).
void loadFromDisk(CookPlan& p, const std::vector<std::vector<int>>& upstream, DiskCache& disk,
                  ValueCache& cache) {
  DecodeMemo memo;
  for (auto it = p.order.rbegin(); it != p.order.rend(); ++it) {
    if (!p.toCook[*it]) continue;
    for (int u : upstream[*it]) {
      if (!p.diskPending[u]) continue;
      p.diskPending[u] = false;
      NodeReport& r = p.reports[u];
      std::optional<std::vector<Value>> outputs = disk.readOutputs(p.keys[u], *r.decl, memo);
      if (outputs) {
        r.outputs = std::move(*outputs);
        cache.insert(p.keys[u], CacheEntry{r.outputs, r.messages, r.seconds, 0, r.files});
        continue;
      }
      r.state = NodeState::NotRequested;
      r.fromDisk = false;
      r.messages.clear();
      r.files.clear();
      r.seconds = 0;
      --p.cached;
      p.toCook[u] = true;
    }
  }
}

}  // namespace

CookPlan gatherCook(const Graph& graph, const CookOptions& options, ValueCache& cache) {
  CookPlan p;
  p.graph = &graph;
  p.order = topologicalOrder(graph);
  p.needed = upstreamClosure(graph, targetIndices(graph, options.targets));
  p.paths = makePathContext(graph, options.outDir, options.baseDir);
  p.keys = computeNodeKeys(graph, {p.paths, options.hashInputFileStamps});
  p.incoming = incomingLinks(graph);
  const std::size_t n = graph.nodeCount();
  p.reports.resize(n);
  p.toCook.assign(n, false);
  p.diskPending.assign(n, false);
  p.waitingOn.assign(n, 0);
  p.dependents.resize(n);
  for (int i : p.order) {
    if (!p.needed[i]) continue;
    ++p.requested;
    NodeReport& r = p.reports[i];
    const Node& node = graph.nodes()[i];
    r.node = node.name();
    r.type = node.type().name();
    r.decl = &node.decl();
    r.key = p.keys[i];
    const std::shared_ptr<const CacheEntry> entry = cache.find(p.keys[i]);
    if (validCacheEntry(entry.get(), node.decl(), &r.filesChanged)) {
      r.state = NodeState::Cached;
      r.outputs = entry->outputs;
      r.messages = entry->messages;
      r.seconds = entry->seconds;
      r.files = entry->files;
      ++p.cached;
    } else if (!lookOnDisk(p, i, options)) {
      p.toCook[i] = true;
    }
  }
  const std::vector<std::vector<int>> upstream = upstreamNodes(graph);
  if (options.diskCache) loadFromDisk(p, upstream, *options.diskCache, cache);
  for (std::size_t i = 0; i < n; ++i) {
    if (!p.toCook[i]) continue;
    for (int u : upstream[i])
      if (p.toCook[u]) {
        ++p.waitingOn[i];
        p.dependents[u].push_back(static_cast<int>(i));
      }
  }
  return p;
}

CookResult storeCook(CookPlan& p, const CookOptions& options, ValueCache& cache) {
  CookResult result;
  for (int i : p.order) {
    if (!p.needed[i]) continue;
    NodeReport& r = p.reports[i];
    if (r.state == NodeState::Cooked) {
      CacheEntry entry{r.outputs, r.messages, r.seconds, 0, r.files};
      if (options.diskCache) options.diskCache->store(p.keys[i], *r.decl, entry);
      cache.insert(p.keys[i], std::move(entry));
    }
    result.reports.push_back(std::move(r));
  }
  if (options.diskCache) options.diskCache->evict();
  result.cancelled =
      (options.cancel && options.cancel->load()) || result.count(NodeState::Cancelled) > 0;
  return result;
}

}  // namespace tfd::graph
