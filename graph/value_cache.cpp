#include "graph/value_cache.h"

namespace tfd::graph {

std::size_t ValueCache::entryBytes(const CacheEntry& entry) {
  std::size_t bytes = 128;
  for (const Value& v : entry.outputs) bytes += v.byteSize();
  for (const NodeMessage& m : entry.messages) bytes += m.text.size() + 32;
  for (const FileStamp& f : entry.files) bytes += f.path.native().size() + 32;
  return bytes;
}

std::shared_ptr<const CacheEntry> ValueCache::find(const Hash& key) {
  std::lock_guard lock(mutex_);
  auto it = slots_.find(key);
  if (it == slots_.end()) return nullptr;
  lru_.splice(lru_.begin(), lru_, it->second.lru);
  return it->second.entry;
}

bool ValueCache::contains(const Hash& key) const {
  std::lock_guard lock(mutex_);
  return slots_.count(key) != 0;
}

std::shared_ptr<const CacheEntry> ValueCache::peek(const Hash& key) const {
  std::lock_guard lock(mutex_);
  auto it = slots_.find(key);
  return it == slots_.end() ? nullptr : it->second.entry;
}

void ValueCache::insert(const Hash& key, CacheEntry entry) {
  entry.bytes = entryBytes(entry);
  auto shared = std::make_shared<const CacheEntry>(std::move(entry));
  std::lock_guard lock(mutex_);
  if (auto it = slots_.find(key); it != slots_.end()) {
    bytes_ -= it->second.entry->bytes;
    lru_.erase(it->second.lru);
    slots_.erase(it);
  }
  lru_.push_front(key);
  bytes_ += shared->bytes;
  slots_.emplace(key, Slot{std::move(shared), lru_.begin()});
  evictLocked();
}

void ValueCache::erase(const Hash& key) {
  std::lock_guard lock(mutex_);
  auto it = slots_.find(key);
  if (it == slots_.end()) return;
  bytes_ -= it->second.entry->bytes;
  lru_.erase(it->second.lru);
  slots_.erase(it);
}

void ValueCache::clear() {
  std::lock_guard lock(mutex_);
  slots_.clear();
  lru_.clear();
  bytes_ = 0;
}

void ValueCache::setBudget(std::size_t bytes) {
  std::lock_guard lock(mutex_);
  budget_ = bytes;
  evictLocked();
}

std::size_t ValueCache::budget() const {
  std::lock_guard lock(mutex_);
  return budget_;
}
std::size_t ValueCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}
std::size_t ValueCache::size() const {
  std::lock_guard lock(mutex_);
  return slots_.size();
}
std::uint64_t ValueCache::evictions() const {
  std::lock_guard lock(mutex_);
  return evictions_;
}

void ValueCache::evictLocked() {
  while (bytes_ > budget_ && !lru_.empty()) {
    auto it = slots_.find(lru_.back());
    bytes_ -= it->second.entry->bytes;
    slots_.erase(it);
    lru_.pop_back();
    ++evictions_;
  }
}

}  // namespace tfd::graph
