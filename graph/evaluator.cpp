#include "graph/evaluator.h"

#include "graph/cook_phases.h"
#include "graph/node_keys.h"
#include "graph/paths.h"
#include "graph/topology.h"

namespace tfd::graph {

std::string_view stateName(NodeState state) {
  switch (state) {
    case NodeState::NotRequested:
      return "not requested";
    case NodeState::Cooked:
      return "cooked";
    case NodeState::Cached:
      return "cached";
    case NodeState::Failed:
      return "failed";
    case NodeState::UpstreamFailed:
      return "upstream failed";
    case NodeState::Cancelled:
      return "cancelled";
  }
  return "?";
}

bool NodeReport::hasWarnings() const {
  for (const NodeMessage& m : messages)
    if (m.severity == Severity::Warning) return true;
  return false;
}

const NodeReport* CookResult::report(std::string_view node) const {
  for (const NodeReport& r : reports)
    if (r.node == node) return &r;
  return nullptr;
}

Value CookResult::output(std::string_view node, std::string_view port) const {
  const NodeReport* r = report(node);
  if (!r || !r->decl || r->outputs.empty()) return {};
  const int i = r->decl->outputIndex(port);
  return i < 0 ? Value{} : r->outputs[i];
}

std::size_t CookResult::count(NodeState state) const {
  std::size_t n = 0;
  for (const NodeReport& r : reports) n += r.state == state;
  return n;
}

bool CookResult::ok() const {
  if (cancelled) return false;
  for (const NodeReport& r : reports)
    if (r.hasError() || r.state == NodeState::Cancelled) return false;
  return true;
}

bool CookResult::hasWarnings() const {
  for (const NodeReport& r : reports)
    if (r.hasWarnings()) return true;
  return false;
}

std::vector<WrittenFile> CookResult::writtenFiles() const {
  std::vector<WrittenFile> out;
  for (const NodeReport& r : reports)
    if (r.state == NodeState::Cooked)
      for (const FileStamp& f : r.files) out.push_back({r.node, f.path});
  return out;
}

Evaluator::Evaluator(std::size_t cacheBudgetBytes) : cache_(cacheBudgetBytes) {}

std::vector<std::string> Evaluator::dirtyNodes(const Graph& graph,
                                               const CookOptions& options) const {
  const std::vector<bool> needed = upstreamClosure(graph, targetIndices(graph, options.targets));
  const KeyOptions keyOptions{makePathContext(graph, options.outDir, options.baseDir),
                              options.hashInputFileStamps};
  const std::vector<Hash> keys = computeNodeKeys(graph, keyOptions);
  std::vector<std::string> out;
  for (int i : topologicalOrder(graph)) {
    const Node& node = graph.nodes()[i];
    if (needed[i] && !validCacheEntry(cache_.peek(keys[i]).get(), node.decl()))
      out.push_back(node.name());
  }
  return out;
}

CookResult Evaluator::cook(const Graph& graph, const CookOptions& options) {
  CookPlan plan = gatherCook(graph, options, cache_);
  runCook(plan, options);
  return storeCook(plan, options, cache_);
}

}  // namespace tfd::graph
