#pragma once
// Deterministic parallel loops and reductions on top of TBB.
//
// Loops hand out index ranges to threads; every output element is written by exactly one
// task, so results never depend on the thread count. Reductions cut the index range into
// fixed chunks of kChunk entries (independent of the thread count), reduce each chunk
// sequentially in parallel, and add the chunk results in chunk order on the calling thread:
// the floating-point result is bitwise identical for 1, 2 or any number of threads.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace tfd::core::linalg {

inline constexpr std::size_t kChunk = 4096;

/// f(begin, end) over [0, n) in parallel, in ranges of at least `grain` indices.
template <class F>
void parallelRanges(std::size_t n, F&& f, std::size_t grain = 1024) {
  if (n == 0) return;
  if (n <= grain) {
    f(std::size_t{0}, n);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

/// W sums: chunk(begin, end, partial) adds the contributions of [begin, end) to partial[0..W);
/// chunks are fixed (kChunk indices) and combined in order, hence deterministic.
template <int W, class F>
std::array<double, W> deterministicSums(std::size_t n, F&& chunk) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::array<double, W> total{};
  if (chunks == 0) return total;
  if (chunks == 1) {
    chunk(std::size_t{0}, n, total);
    return total;
  }
  std::vector<std::array<double, W>> partial(chunks);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t c = r.begin(); c != r.end(); ++c) {
                        partial[c].fill(0.0);
                        chunk(c * kChunk, std::min(n, (c + 1) * kChunk), partial[c]);
                      }
                    });
  for (const auto& p : partial)
    for (int k = 0; k < W; ++k) total[k] += p[k];
  return total;
}

}  // namespace tfd::core::linalg
