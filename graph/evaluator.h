#pragma once
// Cooking a graph: pull-based, in dependency order, cached by content hash.
//
// cook() takes the requested nodes (default: every node whose outputs feed no link, i.e. the
// sinks/exporters and dangling results, which together pull the whole graph) and their
// upstream closure. Nodes whose key (node_keys.h) is in the cache are not cooked; the others
// cook as soon as their inputs are ready.
//
// Phases (cook_phases.h): gather decides, single-threaded, which requested nodes to cook
// (keys, cache hits, side-effect files still intact); run cooks them, independent branches in
// parallel (TBB task_group); store inserts the results into the cache in topological order and
// assembles the CookResult. Each node's outputs and messages depend only on its parameters and
// inputs, so the result (values, states, messages, their order) is identical for any thread
// count and schedule.
//
// Failures: any std::exception from a node's cook becomes that node's error (state Failed,
// message kind CookFailed); downstream nodes get state UpstreamFailed with one message of kind
// UpstreamFailed per failed input link (port order, then link order; port and failing node as
// fields, text "input 'field' failed upstream in node \"X\"") and are not cooked; unrelated
// branches still cook. A required input without a link fails its node (kind MissingInput,
// "required input 'mesh' is not connected").
//
// Side-effect nodes (NodeDecl::sideEffect, the exporters) report the files they wrote
// (CookContext::wroteFile); their size and modification time are kept with the cache entry. A
// later cook of the same Evaluator re-runs such a node, although its key is cached, when one
// of those files is missing or its size or modification time differs; otherwise the files are
// left alone (not rewritten).
//
// On-disk cache (CookOptions::diskCache): gather also looks a missing key up on disk (entry
// description only); before running, in reverse topological order, the values of disk hits
// that a node to cook needs are read; one that cannot be read (damaged) is cooked instead,
// which may in turn need its own inputs. Store writes every cooked node with codecs to disk.
//
// Cancellation: set *CookOptions::cancel. Nodes not yet started are skipped, a running node
// sees CookContext::cancelFlag(); any node that finishes (normally or by throwing) while the
// flag is set is marked Cancelled and its outputs are discarded, so the cache never holds a
// result of an interrupted cook. Nodes that completed before the flag was set stay cached.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/file_stamp.h"
#include "graph/graph.h"
#include "graph/hash.h"
#include "graph/node_message.h"
#include "graph/value_cache.h"

namespace tfd::graph {

class DiskCache;

enum class NodeState {
  NotRequested,    ///< outside the requested nodes' upstream closure
  Cooked,          ///< cook ran and succeeded
  Cached,          ///< result taken from the cache, cook not called
  Failed,          ///< cook threw, or a required input is unconnected, or an output was not set
  UpstreamFailed,  ///< an input's node failed; not cooked
  Cancelled,       ///< cancelled before or while cooking; nothing kept
};
std::string_view stateName(NodeState state);

struct NodeReport {
  std::string node;
  std::string type;
  NodeState state = NodeState::NotRequested;
  std::vector<NodeMessage> messages;  ///< for Cached: the messages of the cook that produced it
  double seconds = 0;                 ///< wall time of this cook (Cached: of the original cook)
  bool cookCalled = false;            ///< the node's cook function ran in this cook
  bool fromDisk = false;  ///< Cached: taken from CookOptions::diskCache, not from memory
  Hash key;
  std::string failedNode;  ///< UpstreamFailed: the (first) node whose failure reached here
  /// Side-effect nodes. Cooked: the files this cook wrote, in the order the node reported
  /// them. Cached: the files of the cook that produced the entry, found unchanged on disk.
  std::vector<FileStamp> files;
  bool filesChanged = false;  ///< cooked although cached: a file it had written was changed
  /// Cooked/Cached: in declaration order. A node cached on disk whose values no cooked node
  /// needed is not loaded: its outputs stay empty.
  std::vector<Value> outputs;
  const NodeDecl* decl = nullptr;  ///< the node type's declaration (owned by the registry)

  bool hasError() const { return state == NodeState::Failed || state == NodeState::UpstreamFailed; }
  bool hasWarnings() const;
};

struct WrittenFile {
  std::string node;
  std::filesystem::path path;
  bool operator==(const WrittenFile&) const = default;
};

struct CookResult {
  std::vector<NodeReport> reports;  ///< the requested closure, upstream before downstream
  bool cancelled = false;

  const NodeReport* report(std::string_view node) const;
  /// The value on node.port when that node was cooked or cached; empty otherwise.
  Value output(std::string_view node, std::string_view port) const;
  template <class T>
  std::shared_ptr<const T> output(std::string_view node, std::string_view port) const {
    return output(node, port).as<T>();
  }
  std::size_t count(NodeState state) const;
  /// No node failed and nothing was cancelled.
  bool ok() const;
  bool hasWarnings() const;
  /// The files written by this cook (nodes in state Cooked): report order, then the order
  /// each node reported them. Cached exporters wrote nothing and are not listed.
  std::vector<WrittenFile> writtenFiles() const;
};

/// Notified while cooking, from TBB worker threads, possibly concurrently: implementations
/// must be thread-safe and must not throw.
class CookObserver {
 public:
  virtual ~CookObserver() = default;
  /// Before anything cooks: the number of requested nodes and how many were found cached.
  virtual void cookStarted(std::size_t requested, std::size_t cached) {
    (void)requested, (void)cached;
  }
  virtual void nodeStarted(const std::string& node, const std::string& type) {
    (void)node, (void)type;
  }
  virtual void nodeProgress(const std::string& node, double fraction, std::string_view stage) {
    (void)node, (void)fraction, (void)stage;
  }
  /// Every requested node once (cached ones first, before cooking starts).
  virtual void nodeFinished(const NodeReport& report) { (void)report; }
};

struct CookOptions {
  std::vector<std::string> targets{};  ///< nodes to cook with their upstream; empty: all leaves
  std::filesystem::path outDir{};      ///< relative output files go here (default: graph folder)
  std::filesystem::path baseDir{};     ///< relative input files (default: graph folder or cwd)
  const std::atomic<bool>* cancel = nullptr;
  CookObserver* observer = nullptr;
  bool hashInputFileStamps = true;  ///< input files' size and mtime feed the cache key
  bool parallel = true;             ///< false: one node at a time, in topological order
  /// On-disk cache (disk_cache.h) consulted after the in-memory one: a node found there is
  /// Cached (fromDisk), and its values are read only when a node that cooks needs them; a
  /// damaged entry is a miss. Cooked nodes are written to it, then it is trimmed to its budget.
  DiskCache* diskCache = nullptr;
};

class Evaluator {
 public:
  static constexpr std::size_t kDefaultCacheBudget = std::size_t(2) << 30;  // 2 GiB

  explicit Evaluator(std::size_t cacheBudgetBytes = kDefaultCacheBudget);

  /// Throws GraphError for an unknown target; everything else is reported per node.
  CookResult cook(const Graph& graph, const CookOptions& options = {});

  /// The requested nodes (default: the whole graph) whose result is not cached (or, for a
  /// side-effect node, whose files changed on disk), in topological order: what the next
  /// cook() would compute. Does not change cache recency.
  std::vector<std::string> dirtyNodes(const Graph& graph, const CookOptions& options = {}) const;

  ValueCache& cache() { return cache_; }
  const ValueCache& cache() const { return cache_; }

 private:
  ValueCache cache_;
};

}  // namespace tfd::graph
