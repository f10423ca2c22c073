// The run phase of a cook (cook_phases.h): scheduling, and cooking one node.
#include <tbb/task_group.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>

#include "graph/cook_context.h"
#include "graph/cook_phases.h"

namespace tfd::graph {

namespace {

bool isCancelled(const CookOptions& options) { return options.cancel && options.cancel->load(); }

NodeMessage cookError(std::string text, MessageKind kind, std::string port = {}) {
  NodeMessage m;
  m.severity = Severity::Error;
  m.text = std::move(text);
  m.kind = kind;
  m.port = std::move(port);
  return m;
}

/// Collects node i's input values. False, with the report's state and messages set, when the
/// node cannot cook: an input's node was cancelled (Cancelled), failed (UpstreamFailed: one
/// message per input port and failing node, port order then link order), or a required input
/// is unconnected (Failed).
bool gatherInputs(CookPlan& p, int i, std::vector<std::vector<Value>>& inputs) {
  const Graph& graph = *p.graph;
  const NodeDecl& decl = graph.nodes()[i].decl();
  NodeReport& r = p.reports[i];
  inputs.assign(decl.inputs().size(), {});
  std::vector<NodeMessage> upstreamFailures, missing;
  bool upstreamCancelled = false;
  for (std::size_t k = 0; k < decl.inputs().size(); ++k) {
    const PortDecl& port = decl.inputs()[k];
    const std::vector<Link>& links = p.incoming[i][k];
    if (links.empty() && !port.optional) missing.push_back(missingInputMessage(port.name));
    const std::size_t firstOfPort = upstreamFailures.size();
    for (const Link& link : links) {
      const NodeReport& ur = p.reports[graph.nodeIndex(link.from.node)];
      if (ur.state == NodeState::Cooked || ur.state == NodeState::Cached) {
        inputs[k].push_back(ur.outputs[ur.decl->outputIndex(link.from.port)]);
      } else if (ur.hasError()) {
        const std::string& root = ur.state == NodeState::Failed ? ur.node : ur.failedNode;
        bool seen = false;
        for (std::size_t m = firstOfPort; m < upstreamFailures.size(); ++m)
          seen = seen || upstreamFailures[m].sourceNode == root;
        if (!seen) upstreamFailures.push_back(upstreamFailedMessage(port.name, root));
      } else {
        upstreamCancelled = true;
      }
    }
  }
  if (upstreamCancelled) {
    r.state = NodeState::Cancelled;
    return false;
  }
  if (!upstreamFailures.empty()) {
    r.state = NodeState::UpstreamFailed;
    r.failedNode = upstreamFailures.front().sourceNode;
    r.messages = std::move(upstreamFailures);
    return false;
  }
  if (!missing.empty()) {
    r.state = NodeState::Failed;
    r.messages = std::move(missing);
    return false;
  }
  return true;
}

/// Calls the node type's cook function; the error it threw, if any.
std::optional<NodeMessage> callCook(const Node& node, CookContext& ctx) {
  try {
    node.type().cook()(ctx);
    return std::nullopt;
  } catch (const std::exception& e) {
    std::string text = e.what();
    if (text.empty()) text = "failed (the exception carried no message)";
    return cookError(std::move(text), MessageKind::CookFailed);
  } catch (...) {
    return cookError("failed with an unknown exception (not derived from std::exception)",
                     MessageKind::CookFailed);
  }
}

/// After a successful cook: every output set, every reported file on disk (stamped now).
std::optional<NodeMessage> checkResults(const NodeDecl& decl, CookContext& ctx, NodeReport& r) {
  for (std::size_t k = 0; k < decl.outputs().size(); ++k)
    if (!ctx.outputs()[k]) {
      const std::string& port = decl.outputs()[k].name;
      return cookError("output '" + port + "' was not set by the node", MessageKind::OutputNotSet,
                       port);
    }
  for (const std::filesystem::path& path : ctx.writtenFiles()) {
    FileStamp stamp = stampFile(path);
    if (!stamp.exists)
      return cookError("reported writing " + path.string() + " but there is no such file",
                       MessageKind::CookFailed);
    r.files.push_back(std::move(stamp));
  }
  return std::nullopt;
}

}  // namespace

void cookNode(CookPlan& p, int i, const CookOptions& options) {
  using Clock = std::chrono::steady_clock;
  NodeReport& r = p.reports[i];
  if (isCancelled(options)) {
    r.state = NodeState::Cancelled;
    return;
  }
  std::vector<std::vector<Value>> inputs;
  if (!gatherInputs(p, i, inputs)) return;

  const Node& node = p.graph->nodes()[i];
  const NodeDecl& decl = node.decl();
  CookObserver* observer = options.observer;
  if (observer) observer->nodeStarted(r.node, r.type);
  CookContext::ProgressCallback progress;
  if (observer)
    progress = [observer, &r](double fraction, std::string_view stage) {
      observer->nodeProgress(r.node, fraction, stage);
    };
  CookContext ctx(r.node, decl, resolvedParams(node, p.paths), std::move(inputs), options.cancel,
                  std::move(progress));
  const auto start = Clock::now();
  r.cookCalled = true;
  std::optional<NodeMessage> error = callCook(node, ctx);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.messages = std::move(ctx.messages());
  if (isCancelled(options)) {
    r.state = NodeState::Cancelled;
    return;
  }
  if (!error) error = checkResults(decl, ctx, r);
  if (error) {
    r.state = NodeState::Failed;
    r.files.clear();
    r.messages.push_back(std::move(*error));
    return;
  }
  r.state = NodeState::Cooked;
  r.outputs = std::move(ctx.outputs());
}

void runCook(CookPlan& p, const CookOptions& options) {
  CookObserver* observer = options.observer;
  if (observer) {
    observer->cookStarted(p.requested, p.cached);
    for (int i : p.order)
      if (p.needed[i] && !p.toCook[i]) observer->nodeFinished(p.reports[i]);
  }
  auto cookOne = [&](int i) {
    cookNode(p, i, options);
    if (observer) observer->nodeFinished(p.reports[i]);
  };
  if (!options.parallel) {
    for (int i : p.order)
      if (p.toCook[i]) cookOne(i);
    return;
  }
  std::vector<std::atomic<int>> pending(p.waitingOn.size());
  for (std::size_t i = 0; i < pending.size(); ++i)
    pending[i].store(p.waitingOn[i], std::memory_order_relaxed);
  tbb::task_group group;
  std::function<void(int)> run = [&](int i) {
    cookOne(i);
    for (int d : p.dependents[i])
      if (pending[d].fetch_sub(1, std::memory_order_acq_rel) == 1) group.run([&run, d] { run(d); });
  };
  for (int i : p.order)
    if (p.toCook[i] && p.waitingOn[i] == 0) group.run([&run, i] { run(i); });
  group.wait();
}

}  // namespace tfd::graph
