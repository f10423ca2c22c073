#include "core/derived_cache.h"

#include <algorithm>

#include "core/memory_budget.h"

namespace tfd::core {

std::size_t DerivedCache::defaultBudget() {
  const std::uint64_t eighth = memoryBudget() / 8;
  return static_cast<std::size_t>(std::min<std::uint64_t>(eighth, std::uint64_t(1) << 30));
}

std::vector<std::shared_ptr<const void>> DerivedCache::candidates(
    const std::shared_ptr<const void>& owner, std::type_index type, std::uint64_t key) {
  std::lock_guard lock(mutex_);
  dropDeadOwnersLocked();
  std::vector<std::shared_ptr<const void>> out;
  // An entry whose owner lives and sits at `owner`'s address belongs to `owner`.
  for (const Entry& e : entries_)
    if (e.ownerAddress == owner.get() && e.type == type && e.key == key) out.push_back(e.value);
  return out;
}

void DerivedCache::touch(const void* value) {
  std::lock_guard lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end(); ++it)
    if (it->value.get() == value) {
      entries_.splice(entries_.begin(), entries_, it);
      return;
    }
}

void DerivedCache::storeErased(const std::shared_ptr<const void>& owner, std::type_index type,
                               std::uint64_t key, std::shared_ptr<const void> value,
                               std::size_t bytes) {
  std::lock_guard lock(mutex_);
  if (!budgetSet_) {
    budget_ = defaultBudget();
    budgetSet_ = true;
  }
  dropDeadOwnersLocked();
  entries_.push_front({owner, owner.get(), type, key, std::move(value), bytes});
  bytes_ += bytes;
  evictLocked();
}

void DerivedCache::dropDeadOwnersLocked() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->owner.expired()) {
      bytes_ -= it->bytes;
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
}

void DerivedCache::evictLocked() {
  while ((bytes_ > budget_ || entries_.size() > kMaxEntries) && !entries_.empty()) {
    bytes_ -= entries_.back().bytes;
    entries_.pop_back();
  }
}

void DerivedCache::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
  bytes_ = 0;
}

void DerivedCache::setBudget(std::size_t bytes) {
  std::lock_guard lock(mutex_);
  budget_ = bytes;
  budgetSet_ = true;
  evictLocked();
}

std::size_t DerivedCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

std::size_t DerivedCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

DerivedCache& derivedCache() {
  static DerivedCache cache;
  return cache;
}

}  // namespace tfd::core
