#pragma once
// Results derived from an immutable object (a mesh) that are costly to recompute and may be
// asked for again: a harmonic solver's multigrid set-up, which a re-cook after a constraint
// value change needs again for the same mesh and matrix. One process-wide cache, bounded by a
// byte budget and an entry count, least recently used evicted first. Each entry belongs to
// an owner object (held weakly: the cache never keeps a mesh alive) and is found only while
// that owner lives; entries of a destroyed owner are dropped at the next lookup or store.
// Entries are looked up by owner, type and a 64-bit key; the caller then checks exactly that
// an entry fits (keys may collide), so a cached entry is used only when it equals what would
// be built. Thread-safe.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <typeindex>
#include <vector>

namespace tfd::core {

class DerivedCache {
 public:
  /// At most this many entries are kept (lookups scan them).
  static constexpr std::size_t kMaxEntries = 16;
  /// The budget unless setBudget() was called: an eighth of core::memoryBudget(), at most
  /// 1 GiB.
  static std::size_t defaultBudget();

  DerivedCache() = default;
  DerivedCache(const DerivedCache&) = delete;
  DerivedCache& operator=(const DerivedCache&) = delete;

  /// The most recently used entry of `owner` of type T under `key` that `fits` accepts (then
  /// marked most recently used); null when there is none. `fits` runs without the cache's
  /// lock (it may run parallel work that uses this cache too).
  template <class T>
  std::shared_ptr<const T> find(const std::shared_ptr<const void>& owner, std::uint64_t key,
                                const std::function<bool(const T&)>& fits) {
    for (const auto& candidate : candidates(owner, typeid(T), key)) {
      if (!fits(*static_cast<const T*>(candidate.get()))) continue;
      touch(candidate.get());
      return std::static_pointer_cast<const T>(candidate);
    }
    return nullptr;
  }

  /// Adds an entry of about `bytes` bytes for `owner`, then evicts least recently used
  /// entries beyond the budget or kMaxEntries (an entry larger than the budget is not kept).
  template <class T>
  void store(const std::shared_ptr<const void>& owner, std::uint64_t key,
             std::shared_ptr<const T> value, std::size_t bytes) {
    storeErased(owner, typeid(T), key, std::move(value), bytes);
  }

  void clear();
  /// Sets the budget (evicting at once).
  void setBudget(std::size_t bytes);
  std::size_t bytes() const;
  std::size_t size() const;

 private:
  struct Entry {
    std::weak_ptr<const void> owner;
    const void* ownerAddress;
    std::type_index type;
    std::uint64_t key;
    std::shared_ptr<const void> value;
    std::size_t bytes;
  };
  std::vector<std::shared_ptr<const void>> candidates(const std::shared_ptr<const void>& owner,
                                                      std::type_index type, std::uint64_t key);
  void touch(const void* value);
  void storeErased(const std::shared_ptr<const void>& owner, std::type_index type,
                   std::uint64_t key, std::shared_ptr<const void> value, std::size_t bytes);
  void dropDeadOwnersLocked();
  void evictLocked();

  mutable std::mutex mutex_;
  std::list<Entry> entries_;  ///< most recently used first
  std::size_t bytes_ = 0;
  std::size_t budget_ = 0;
  bool budgetSet_ = false;
};

/// The process's cache of results derived from meshes (core::HarmonicSolver's set-ups).
DerivedCache& derivedCache();

}  // namespace tfd::core
