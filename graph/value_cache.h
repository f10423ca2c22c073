#pragma once
// The content-hash cache of cooked nodes: node key -> the node's outputs and messages.
// Memory-bounded: each entry's size is the sum of its values' approximate byte sizes (see
// TFD_GRAPH_VALUE_TYPE_SIZED); beyond the budget the least recently used entries are evicted
// (an entry larger than the whole budget is therefore not kept). Values are shared pointers, so
// evicting never invalidates a value still in use. Thread-safe.
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "graph/file_stamp.h"
#include "graph/hash.h"
#include "graph/node_message.h"
#include "graph/value.h"

namespace tfd::graph {

struct CacheEntry {
  std::vector<Value> outputs;         ///< in declaration order
  std::vector<NodeMessage> messages;  ///< info and warnings of the cook that produced it
  double seconds = 0;                 ///< that cook's duration
  std::size_t bytes = 0;              ///< filled by insert()
  std::vector<FileStamp> files{};     ///< side-effect nodes: the files that cook wrote
};

class ValueCache {
 public:
  explicit ValueCache(std::size_t budgetBytes) : budget_(budgetBytes) {}

  /// The entry, marked most recently used; null when absent.
  std::shared_ptr<const CacheEntry> find(const Hash& key);
  /// Presence test that does not change recency.
  bool contains(const Hash& key) const;
  /// The entry without changing recency; null when absent.
  std::shared_ptr<const CacheEntry> peek(const Hash& key) const;
  /// Inserts (or replaces) and evicts least recently used entries beyond the budget.
  void insert(const Hash& key, CacheEntry entry);
  void erase(const Hash& key);
  void clear();

  void setBudget(std::size_t bytes);
  std::size_t budget() const;
  std::size_t bytes() const;  ///< sum of the entries' sizes
  std::size_t size() const;   ///< number of entries
  std::uint64_t evictions() const;

  /// Approximate size of an entry: its values' sizes plus a small fixed overhead.
  static std::size_t entryBytes(const CacheEntry& entry);

 private:
  void evictLocked();
  struct Slot {
    std::shared_ptr<const CacheEntry> entry;
    std::list<Hash>::iterator lru;
  };
  mutable std::mutex mutex_;
  std::size_t budget_;
  std::size_t bytes_ = 0;
  std::uint64_t evictions_ = 0;
  std::list<Hash> lru_;  // front: most recently used
  std::unordered_map<Hash, Slot> slots_;
};

}  // namespace tfd::graph
