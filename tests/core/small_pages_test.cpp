// SmallPagesScope (core/small_pages.h): the flag is set while scopes are open and restored
// after the last one closes, nested or overlapping across threads; a process that had it keeps
// it; and memory first touched inside a scope is not backed by huge pages where it would be
// outside (checked in /proc/self/smaps when the machine gives huge pages at all).
#include "core/small_pages.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/prctl.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <latch>
#include <sstream>
#include <string>
#include <thread>

namespace tfd::core {
namespace {

/// Skips unless the kernel has the setting and the process starts without it.
#define REQUIRE_CLEAR_FLAG()                                                    \
  do {                                                                          \
    const int flag = prctl(PR_GET_THP_DISABLE, 0, 0, 0, 0);                     \
    if (flag < 0) GTEST_SKIP() << "no PR_GET_THP_DISABLE on this kernel";       \
    if (flag != 0) GTEST_SKIP() << "the process was started with THP disabled"; \
  } while (false)

TEST(SmallPages, NestedScopesSetTheFlagAndTheLastRestoresIt) {
  REQUIRE_CLEAR_FLAG();
  EXPECT_FALSE(smallPagesOnly());
  {
    const SmallPagesScope outer;
    EXPECT_TRUE(smallPagesOnly());
    {
      const SmallPagesScope inner;
      EXPECT_TRUE(smallPagesOnly());
    }
    EXPECT_TRUE(smallPagesOnly());
  }
  EXPECT_FALSE(smallPagesOnly());
}

TEST(SmallPages, AProcessStartedWithTheFlagKeepsIt) {
  REQUIRE_CLEAR_FLAG();
  ASSERT_EQ(prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0), 0);
  { const SmallPagesScope scope; }
  EXPECT_TRUE(smallPagesOnly());
  ASSERT_EQ(prctl(PR_SET_THP_DISABLE, 0, 0, 0, 0), 0);
}

TEST(SmallPages, ScopesOverlappingAcrossThreads) {
  REQUIRE_CLEAR_FLAG();
  // A opens, B opens, A closes (B still open: the flag stays), B closes (cleared).
  std::latch bothOpen(2), aClosed(1);
  bool whileBOnly = false;
  std::thread a([&] {
    const SmallPagesScope scope;
    bothOpen.arrive_and_wait();
  });
  std::thread b([&] {
    const SmallPagesScope scope;
    bothOpen.arrive_and_wait();
    aClosed.wait();
    whileBOnly = smallPagesOnly();
  });
  a.join();
  aClosed.count_down();
  b.join();
  EXPECT_TRUE(whileBOnly);
  EXPECT_FALSE(smallPagesOnly());
}

/// AnonHugePages (kB) of the mapping that holds `p`, from /proc/self/smaps.
long hugeKilobytesAt(const void* p) {
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t from = 0, to = 0;
    if (std::sscanf(line.c_str(), "%lx-%lx ", &from, &to) == 2 && line.find(' ') > 8) {
      inside = from <= at && at < to;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      return std::stol(line.substr(14));
    }
  }
  return -1;
}

/// Touches every page of a fresh 8 MB mapping advised for huge pages; returns its huge kB.
long touchAdvised() {
  constexpr std::size_t kBytes = std::size_t(8) << 20;
  void* p = mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return -1;
  madvise(p, kBytes, MADV_HUGEPAGE);
  for (std::size_t i = 0; i < kBytes; i += 4096) static_cast<char*>(p)[i] = 1;
  const long huge = hugeKilobytesAt(p);
  munmap(p, kBytes);
  return huge;
}

TEST(SmallPages, MemoryTouchedInsideAScopeHasNoHugePages) {
  REQUIRE_CLEAR_FLAG();
  if (touchAdvised() <= 0) GTEST_SKIP() << "this machine gives no transparent huge pages now";
  const SmallPagesScope scope;
  EXPECT_EQ(touchAdvised(), 0);
}

}  // namespace
}  // namespace tfd::core
