#pragma once
// Transparent huge pages for tfd's large arrays (bench/RESULTS.md, "Performance, issue 14"):
// a 1M-tet cook touches several hundred MB of fresh memory, and on the virtual machines we
// measured each 4 KiB page fault costs microseconds, a quarter of a cached re-cook. glibc maps
// large allocations with huge pages when its tunable glibc.malloc.hugetlb=1 is set, which
// only works from the process's start: so tfd starts itself again with it, once.

namespace tfd::cli {

/// When GLIBC_TUNABLES is not set (a user who sets it, e.g. to glibc.malloc.hugetlb=0, keeps
/// their choice), sets it to glibc.malloc.hugetlb=1 and executes /proc/self/exe again with
/// the same arguments; returns only when that is not possible or not needed.
void restartWithHugePages(char** argv);

}  // namespace tfd::cli
