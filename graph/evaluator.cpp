#include "graph/evaluator.h"

#include <tbb/task_group.h>

#include <chrono>
#include <functional>
#include <set>

#include "graph/cook_context.h"
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

Evaluator::Evaluator(std::size_t cacheBudgetBytes) : cache_(cacheBudgetBytes) {}

namespace {

std::vector<int> targetIndices(const Graph& graph, const std::vector<std::string>& targets) {
  if (targets.empty()) return leafNodes(graph);
  std::vector<int> out;
  for (const std::string& name : targets) {
    (void)graph.node(name);  // throws GraphError for an unknown node
    out.push_back(graph.nodeIndex(name));
  }
  return out;
}

}  // namespace

std::vector<std::string> Evaluator::dirtyNodes(const Graph& graph,
                                               const CookOptions& options) const {
  const std::vector<bool> needed = upstreamClosure(graph, targetIndices(graph, options.targets));
  const KeyOptions keyOptions{makePathContext(graph, options.outDir, options.baseDir),
                              options.hashInputFileStamps};
  const std::vector<Hash> keys = computeNodeKeys(graph, keyOptions);
  std::vector<std::string> out;
  for (int i : topologicalOrder(graph))
    if (needed[i] && !cache_.contains(keys[i])) out.push_back(graph.nodes()[i].name());
  return out;
}

CookResult Evaluator::cook(const Graph& graph, const CookOptions& options) {
  using Clock = std::chrono::steady_clock;
  const std::vector<int> order = topologicalOrder(graph);
  const std::vector<bool> needed = upstreamClosure(graph, targetIndices(graph, options.targets));
  const PathContext paths = makePathContext(graph, options.outDir, options.baseDir);
  const std::vector<Hash> keys = computeNodeKeys(graph, {paths, options.hashInputFileStamps});
  const std::vector<std::vector<int>> upstream = upstreamNodes(graph);
  const auto incoming = incomingLinks(graph);
  const std::size_t n = graph.nodeCount();
  const std::atomic<bool>* cancel = options.cancel;
  auto isCancelled = [cancel] { return cancel && cancel->load(); };
  CookObserver* observer = options.observer;

  std::vector<NodeReport> reports(n);
  std::vector<bool> toCook(n, false);
  std::vector<std::atomic<int>> pending(n);
  std::vector<std::vector<int>> dependents(n);
  std::size_t requested = 0, cached = 0;
  for (int i : order) {
    if (!needed[i]) continue;
    ++requested;
    NodeReport& r = reports[i];
    const Node& node = graph.nodes()[i];
    r.node = node.name();
    r.type = node.type().name();
    r.decl = &node.decl();
    r.key = keys[i];
    if (auto entry = cache_.find(keys[i])) {
      r.state = NodeState::Cached;
      r.outputs = entry->outputs;
      r.messages = entry->messages;
      r.seconds = entry->seconds;
      ++cached;
    } else {
      toCook[i] = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!toCook[i]) continue;
    for (int u : upstream[i])
      if (toCook[u]) {
        pending[i].fetch_add(1, std::memory_order_relaxed);
        dependents[u].push_back(static_cast<int>(i));
      }
  }
  if (observer) {
    observer->cookStarted(requested, cached);
    for (int i : order)
      if (needed[i] && !toCook[i]) observer->nodeFinished(reports[i]);
  }

  auto cookOne = [&](int i) {
    const Node& node = graph.nodes()[i];
    const NodeDecl& decl = node.decl();
    NodeReport& r = reports[i];
    auto finish = [&] {
      if (observer) observer->nodeFinished(r);
    };
    if (isCancelled()) {
      r.state = NodeState::Cancelled;
      return finish();
    }
    // Gather inputs; upstream failure or cancellation stops this node.
    std::vector<std::vector<Value>> inputs(decl.inputs().size());
    bool upstreamCancelled = false;
    std::vector<NodeMessage> problems;
    bool missingRequired = false;
    for (std::size_t k = 0; k < decl.inputs().size(); ++k) {
      const PortDecl& port = decl.inputs()[k];
      const std::vector<Link>& links = incoming[i][k];
      if (links.empty() && !port.optional) {
        missingRequired = true;
        problems.push_back(
            {Severity::Error, "required input '" + port.name + "' is not connected"});
      }
      std::set<std::string> failedHere;
      for (const Link& link : links) {
        const int u = graph.nodeIndex(link.from.node);
        const NodeReport& ur = reports[u];
        if (ur.state == NodeState::Cooked || ur.state == NodeState::Cached) {
          const int out = graph.nodes()[u].decl().outputIndex(link.from.port);
          inputs[k].push_back(ur.outputs[out]);
        } else if (ur.state == NodeState::Failed || ur.state == NodeState::UpstreamFailed) {
          const std::string& root = ur.state == NodeState::Failed ? ur.node : ur.failedNode;
          if (r.failedNode.empty()) r.failedNode = root;
          if (failedHere.insert(root).second)
            problems.push_back({Severity::Error, "input '" + port.name +
                                                     "' failed upstream in node \"" + root + "\""});
        } else {
          upstreamCancelled = true;
        }
      }
    }
    if (upstreamCancelled) {
      r.state = NodeState::Cancelled;
      r.failedNode.clear();
      return finish();
    }
    if (!r.failedNode.empty()) {
      r.state = NodeState::UpstreamFailed;
      for (NodeMessage& m : problems)
        if (m.text.find("failed upstream") != std::string::npos) r.messages.push_back(m);
      return finish();
    }
    if (missingRequired) {
      r.state = NodeState::Failed;
      r.messages = std::move(problems);
      return finish();
    }

    if (observer) observer->nodeStarted(r.node, r.type);
    CookContext::ProgressCallback progress;
    if (observer)
      progress = [observer, &r](double fraction, std::string_view stage) {
        observer->nodeProgress(r.node, fraction, stage);
      };
    CookContext ctx(r.node, decl, resolvedParams(node, paths), std::move(inputs), cancel,
                    std::move(progress));
    std::string error;
    bool threw = false;
    const auto start = Clock::now();
    r.cookCalled = true;
    try {
      node.type().cook()(ctx);
    } catch (const std::exception& e) {
      threw = true;
      error = e.what();
      if (error.empty()) error = "failed (the exception carried no message)";
    } catch (...) {
      threw = true;
      error = "failed with an unknown exception (not derived from std::exception)";
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.messages = std::move(ctx.messages());
    if (isCancelled()) {
      r.state = NodeState::Cancelled;
      return finish();
    }
    if (!threw) {
      for (std::size_t k = 0; k < decl.outputs().size(); ++k)
        if (!ctx.outputs()[k]) {
          threw = true;
          error = "output '" + decl.outputs()[k].name + "' was not set by the node";
          break;
        }
    }
    if (threw) {
      r.state = NodeState::Failed;
      r.messages.push_back({Severity::Error, std::move(error)});
      return finish();
    }
    r.state = NodeState::Cooked;
    r.outputs = std::move(ctx.outputs());
    cache_.insert(keys[i], CacheEntry{r.outputs, r.messages, r.seconds, 0});
    finish();
  };

  if (options.parallel) {
    tbb::task_group group;
    std::function<void(int)> run = [&](int i) {
      cookOne(i);
      for (int d : dependents[i])
        if (pending[d].fetch_sub(1, std::memory_order_acq_rel) == 1)
          group.run([&run, d] { run(d); });
    };
    std::vector<int> roots;  // collected first: running tasks change `pending`
    for (int i : order)
      if (toCook[i] && pending[i].load() == 0) roots.push_back(i);
    for (int i : roots) group.run([&run, i] { run(i); });
    group.wait();
  } else {
    for (int i : order)
      if (toCook[i]) cookOne(i);
  }

  CookResult result;
  for (int i : order)
    if (needed[i]) result.reports.push_back(std::move(reports[i]));
  result.cancelled = isCancelled() || result.count(NodeState::Cancelled) > 0;
  return result;
}

}  // namespace tfd::graph
