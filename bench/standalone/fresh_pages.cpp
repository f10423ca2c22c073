// Standalone measurement, not part of the build: what first touches of memory cost on the
// machine at hand, in milliseconds per MB, for small (4 KiB) and transparent huge (2 MiB)
// pages, each fresh (after the machine has had `pause` seconds to hand freed memory back to
// its host) and recycled (right after another mapping of the same size was freed).
// The answer decides whether glibc.malloc.hugetlb=1 (README, "Huge pages") helps a first cook:
// on the 2-core virtual machines of this project it has ranged from huge pages being the
// cheaper kind (2026-12-02) to fresh huge pages costing 8 times more than small ones
// (2026-12-03, bench/RESULTS.md, "Fresh pages"); recycled huge pages were always the cheapest.
// Build and run by hand:
//   g++ -std=c++20 -O2 bench/standalone/fresh_pages.cpp -o /tmp/fresh_pages
//   /tmp/fresh_pages            # 200 MB, pause 3 s, 3 rounds
//   /tmp/fresh_pages 400 5 4    # MB, pause seconds, rounds
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

constexpr std::size_t kHuge = std::size_t(2) << 20;

/// Milliseconds per MB to write one byte in every 4 KiB page of a new mapping of `mb` MB,
/// advised for huge pages or against them.
double touch(std::size_t mb, bool huge) {
  const std::size_t bytes = mb << 20;
  void* raw =
      mmap(nullptr, bytes + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) {
    std::perror("mmap");
    std::exit(1);
  }
  char* p =
      reinterpret_cast<char*>((reinterpret_cast<std::size_t>(raw) + kHuge - 1) & ~(kHuge - 1));
  madvise(p, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < bytes; i += 4096) p[i] = 1;
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  munmap(raw, bytes + kHuge);
  return ms / static_cast<double>(mb);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t mb = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 200;
  const unsigned pause = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 3;
  const int rounds = argc > 3 ? std::atoi(argv[3]) : 3;
  std::printf("ms per MB touched, %zu MB mappings, %u s pause before each fresh one\n", mb, pause);
  std::printf("round   fresh 4K   fresh 2M   recycled 4K   recycled 2M\n");
  for (int r = 0; r < rounds; ++r) {
    double fresh[2], recycled[2];
    for (const bool huge : {false, true}) {
      sleep(pause);
      fresh[huge] = touch(mb, huge);
      recycled[huge] = touch(mb, huge);
    }
    std::printf("%5d%11.2f%11.2f%14.2f%14.2f\n", r + 1, fresh[0], fresh[1], recycled[0],
                recycled[1]);
  }
}
