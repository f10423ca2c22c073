#pragma once
// The on-disk cook cache (`tfd cook --cache DIR`): one file per cooked node, named by the
// node's content-hash key (node_keys.h), so a later process cooking the same graph (or one
// with only downstream parameters changed) takes unchanged nodes from disk instead of
// re-running them.
//
// Entry file DIR/<32 hex digits of the key>.tfdc, little-endian:
//   offset  size  field
//        0     8  magic "TFDCACHE"
//        8     4  format version (kDiskCacheVersion)
//       12     4  reserved, 0
//       16    16  key (hi, lo)
//       32     8  meta size M           40  8  meta checksum (checksum64 of the meta bytes)
//       48     8  payload size P        56  8  payload checksum (checksum64 of the payload)
//       64     M  meta: node type, typeVersion, seconds, messages, written files (path,
//                 size, mtime), output count and each output's value type name
//     64+M     P  payload: per output, its size (u64) and its codec's bytes (value_codec.h)
// The meta part is read and verified on its own (cheap: it says whether the entry stands for
// the node and which files an exporter left); the payload only when a node that is cooked
// needs the value, from a read-only mapping of the file (no copy of a large payload). Any
// mismatch (magic, version, key, sizes, checksums, a decoder's error) is
// a cache miss with a warning, never a wrong result: the node is cooked again.
//
// Writes go to a temporary file in DIR, renamed over the entry (atomic on one file system).
// Reading an entry marks it recently used (its modification time); after a cook, the least
// recently used entries are removed until the folder's entries fit the size budget.
// Thread-safe.
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "graph/hash.h"
#include "graph/node_decl.h"
#include "graph/value_cache.h"
#include "graph/value_codec.h"

namespace tfd::graph {

// 2: TetMesh values carry their topology ids (nodes/value_codecs.cpp); checksum64 instead of
//    FNV-1a (byte_stream.h).
inline constexpr std::uint32_t kDiskCacheVersion = 2;

class DiskCache {
 public:
  static constexpr std::uint64_t kDefaultBudget = std::uint64_t(2) << 30;  // 2 GiB

  /// Creates the folder when missing; throws GraphError when it cannot.
  DiskCache(std::filesystem::path dir, std::uint64_t budgetBytes, const ValueCodecs& codecs);

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path entryPath(const Hash& key) const;

  /// True when every output of the node type has a codec (only such nodes are stored).
  bool canStore(const NodeDecl& decl) const;
  /// The entry's messages, seconds and files (outputs left empty), verified against the key and
  /// the node type; nothing when absent or damaged (damage adds a warning).
  std::optional<CacheEntry> readMeta(const Hash& key, const NodeDecl& decl);
  /// The entry's decoded outputs; nothing (and a warning) when the payload is damaged.
  std::optional<std::vector<Value>> readOutputs(const Hash& key, const NodeDecl& decl,
                                                DecodeMemo& memo);
  /// Writes the entry atomically; a failure (disk full...) is a warning, never an error.
  void store(const Hash& key, const NodeDecl& decl, const CacheEntry& entry);
  /// Removes the least recently used entries until the total fits the budget.
  void evict();

  /// Warnings so far (damaged entries, failed writes, evictions are not warnings).
  std::vector<std::string> warnings() const;
  /// Entries read (meta), payloads decoded, entries written, entries evicted.
  struct Counters {
    std::uint64_t hits = 0, loads = 0, stores = 0, evictions = 0;
  };
  Counters counters() const;

 private:
  struct Raw;
  std::optional<Raw> readVerified(const Hash& key, bool withPayload);
  void warn(std::string text);

  std::filesystem::path dir_;
  std::uint64_t budget_;
  const ValueCodecs& codecs_;
  mutable std::mutex mutex_;
  std::vector<std::string> warnings_;
  Counters counters_;
};

}  // namespace tfd::graph
