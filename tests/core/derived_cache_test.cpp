// DerivedCache (core/derived_cache.h): lookups by owner, type and key with an exact check by
// the caller, least recently used eviction by bytes and by entry count, entries of destroyed
// owners never found.
#include "core/derived_cache.h"

#include <gtest/gtest.h>

#include <string>

namespace tfd::core {
namespace {

const auto kOwner = std::make_shared<const int>(0);

std::shared_ptr<const int> findInt(DerivedCache& c, std::uint64_t key, int wanted,
                                   const std::shared_ptr<const void>& owner = kOwner) {
  return c.find<int>(owner, key, [&](const int& v) { return v == wanted; });
}

void storeInt(DerivedCache& c, std::uint64_t key, int value, std::size_t bytes,
              const std::shared_ptr<const void>& owner = kOwner) {
  c.store<int>(owner, key, std::make_shared<const int>(value), bytes);
}

TEST(DerivedCache, FindsByTypeKeyAndTheCallersCheck) {
  DerivedCache c;
  c.setBudget(1000);
  storeInt(c, 7, 1, 10);
  storeInt(c, 7, 2, 10);  // same key: both kept
  c.store<std::string>(kOwner, 7, std::make_shared<const std::string>("x"), 10);
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c.bytes(), 30u);
  ASSERT_TRUE(findInt(c, 7, 1));
  EXPECT_EQ(*findInt(c, 7, 2), 2);
  EXPECT_FALSE(findInt(c, 7, 3));  // the check rejects every candidate
  EXPECT_FALSE(findInt(c, 8, 1));  // other key
  EXPECT_FALSE(c.find<double>(kOwner, 7, [](const double&) { return true; }));  // other type
  EXPECT_EQ(*c.find<std::string>(kOwner, 7, [](const std::string&) { return true; }), "x");
}

TEST(DerivedCache, EvictsTheLeastRecentlyUsedBeyondTheBudget) {
  DerivedCache c;
  c.setBudget(25);
  storeInt(c, 1, 1, 10);
  storeInt(c, 2, 2, 10);
  ASSERT_TRUE(findInt(c, 1, 1));  // 1 is now the most recently used
  storeInt(c, 3, 3, 10);
  EXPECT_TRUE(findInt(c, 1, 1));
  EXPECT_FALSE(findInt(c, 2, 2));
  EXPECT_TRUE(findInt(c, 3, 3));
  storeInt(c, 4, 4, 100);  // larger than the budget: not kept
  EXPECT_FALSE(findInt(c, 4, 4));
  EXPECT_LE(c.bytes(), 25u);
  c.setBudget(0);
  EXPECT_EQ(c.size(), 0u);
}

TEST(DerivedCache, KeepsAtMostMaxEntries) {
  DerivedCache c;
  c.setBudget(1 << 20);
  for (int k = 0; k < static_cast<int>(DerivedCache::kMaxEntries) + 3; ++k) storeInt(c, k, k, 1);
  EXPECT_EQ(c.size(), DerivedCache::kMaxEntries);
  EXPECT_FALSE(findInt(c, 0, 0));
  EXPECT_TRUE(findInt(c, DerivedCache::kMaxEntries + 2, DerivedCache::kMaxEntries + 2));
  c.clear();
  EXPECT_EQ(c.size(), 0u);
  EXPECT_EQ(c.bytes(), 0u);
}

TEST(DerivedCache, EntriesBelongToTheirLivingOwner) {
  DerivedCache c;
  c.setBudget(1000);
  auto owner = std::make_shared<const double>(1.0);
  const auto other = std::make_shared<const double>(2.0);
  storeInt(c, 1, 1, 10, owner);
  EXPECT_TRUE(findInt(c, 1, 1, owner));
  EXPECT_FALSE(findInt(c, 1, 1, other));
  std::weak_ptr<const double> watch = owner;
  owner.reset();
  EXPECT_TRUE(watch.expired());  // the cache holds its owner weakly
  EXPECT_FALSE(findInt(c, 1, 1, other));
  EXPECT_EQ(c.size(), 0u);  // dropped with its owner
  EXPECT_EQ(c.bytes(), 0u);
}

TEST(DerivedCache, AnEntryInUseOutlivesItsEviction) {
  DerivedCache c;
  c.setBudget(10);
  storeInt(c, 1, 5, 10);
  const auto held = findInt(c, 1, 5);
  c.clear();
  ASSERT_TRUE(held);
  EXPECT_EQ(*held, 5);
}

}  // namespace
}  // namespace tfd::core
