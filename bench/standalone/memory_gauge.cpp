// Standalone measurement, not part of the build: the two properties of the machine at hand that
// the 1M-tet edits follow most closely, so that figures from different sessions (different
// virtual machines of the same nominal kind) can be compared:
//  - memory latency: a dependent pointer chase through a random cycle over `mb` MB (ns per
//    load). Region growing's distance front and grower, about a third of an edit's CPU time at
//    1M tets, wait on such loads (bench/RESULTS.md, session 12);
//  - memory bandwidth: a triad a[i] = 0.5 a[i] + b[i] over two arrays of `mb` MB each, with one
//    and two threads (GB/s counting three 8-byte streams). The solvers' products read this way.
// Session 12's host (2026-12-03, 128 MB): 185–190 ns, 13–15 GB/s one thread, 14–27 GB/s two.
// Build and run by hand:
//   g++ -std=c++20 -O2 -pthread bench/standalone/memory_gauge.cpp -o /tmp/memory_gauge
//   /tmp/memory_gauge            # 128 MB, 3 rounds
//   /tmp/memory_gauge 256 5      # MB, rounds
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Nanoseconds per load of a chase through one random cycle over `next` (Sattolo's shuffle:
/// every slot is visited once per lap, in an order the prefetchers cannot guess).
double chaseNanoseconds(const std::vector<std::size_t>& next, std::size_t loads) {
  std::size_t at = 0;
  const auto t0 = Clock::now();
  for (std::size_t k = 0; k < loads; ++k) at = next[at];
  const double ns = 1e9 * secondsSince(t0) / double(loads);
  if (at == next.size()) std::puts("");  // keeps the chase
  return ns;
}

/// GB/s of the triad over [0, n) split between `threads` threads.
double triadGigabytes(std::vector<double>& a, const std::vector<double>& b, int threads) {
  const std::size_t n = a.size();
  const auto t0 = Clock::now();
  std::vector<std::thread> workers;
  for (int k = 0; k < threads; ++k)
    workers.emplace_back([&, k] {
      for (std::size_t i = n * k / threads, e = n * (k + 1) / threads; i < e; ++i)
        a[i] = 0.5 * a[i] + b[i];
    });
  for (std::thread& w : workers) w.join();
  return 3.0 * 8.0 * double(n) / secondsSince(t0) / 1e9;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t mb = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 128;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::size_t slots = (mb << 20) / sizeof(std::size_t);
  std::vector<std::size_t> next(slots);
  std::iota(next.begin(), next.end(), std::size_t(0));
  std::mt19937_64 random(12345);
  for (std::size_t i = slots - 1; i > 0; --i)  // Sattolo: a single cycle
    std::swap(next[i], next[std::uniform_int_distribution<std::size_t>(0, i - 1)(random)]);
  std::vector<double> a((mb << 20) / sizeof(double), 1.0), b(a.size(), 2.0);
  std::printf("%zu MB: latency ns per load, triad GB/s with 1 and 2 threads\n", mb);
  std::printf("round   latency   1 thread   2 threads\n");
  for (int r = 1; r <= rounds; ++r) {
    const double ns = chaseNanoseconds(next, 4'000'000);
    const double one = triadGigabytes(a, b, 1), two = triadGigabytes(a, b, 2);
    std::printf("%5d   %7.0f   %8.1f   %9.1f\n", r, ns, one, two);
  }
  return 0;
}
