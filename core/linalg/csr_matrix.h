#pragma once
// Compressed sparse row matrices and the kernels the harmonic solver needs: products with
// W interleaved right-hand sides (one pass over the matrix serves all W columns), transpose,
// sparse-sparse products. Every kernel is parallel (TBB) and deterministic: each output entry
// is computed by one task with a fixed summation order.
//
// Layout of a block vector with W columns and n rows: entry (i, c) at [i * W + c].
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "core/linalg/parallel.h"

namespace tfd::core::linalg {

template <class Real>
struct CsrMatrix {
  int rows = 0;
  int cols = 0;
  std::vector<int> start{0};  ///< rows + 1 offsets into index/value
  std::vector<int> index;     ///< column of each entry (ascending unless stated otherwise)
  std::vector<Real> value;

  std::size_t nonZeros() const { return index.size(); }
  std::size_t bytes() const {
    return start.size() * sizeof(int) + index.size() * sizeof(int) + value.size() * sizeof(Real);
  }
};

/// A CSR matrix's arrays, borrowed: what the product kernels read. Lets a copy of a matrix in
/// another precision share the original's row starts and column indices (the multigrid's float
/// copy of the fine matrix, linalg/amg.h).
template <class Real>
struct CsrView {
  int rows = 0;
  const int* start = nullptr;
  const int* index = nullptr;
  const Real* value = nullptr;
};

template <class Real>
CsrView<Real> view(const CsrMatrix<Real>& a) {
  return {a.rows, a.start.data(), a.index.data(), a.value.data()};
}

/// The same matrix with values converted to another precision.
template <class To, class From>
CsrMatrix<To> convert(const CsrMatrix<From>& a) {
  CsrMatrix<To> out;
  out.rows = a.rows;
  out.cols = a.cols;
  out.start = a.start;
  out.index = a.index;
  out.value.assign(a.value.begin(), a.value.end());
  return out;
}

/// W values of type V as one GCC/Clang vector (split into native SIMD registers by the
/// compiler): the product kernels then use whole-register loads and multiply-adds instead of
/// letting the auto-vectoriser interleave matrix entries.
/// A 16-byte SIMD vector of V (SSE2 on x86-64, NEON elsewhere; GCC/Clang vector extension).
/// Block rows of W values are handled as W·sizeof(V)/16 such vectors: explicit whole-register
/// multiply-adds instead of letting the auto-vectoriser interleave matrix entries, and no
/// vector types wider than the baseline ISA (which GCC lowers poorly).
template <class V>
struct Simd16;
template <>
struct Simd16<float> {
  typedef float type __attribute__((vector_size(16)));
};
template <>
struct Simd16<double> {
  typedef double type __attribute__((vector_size(16)));
};

/// Rows [begin, end) of y = A x (W columns; Real and V may differ, sums in V). With
/// accumulate, y += A x instead.
template <int W, class Real, class V, bool accumulate = false>
inline void multiplyRows(const CsrView<Real>& a, const V* x, V* y, std::size_t begin,
                         std::size_t end) {
  const int* start = a.start;
  const int* index = a.index;
  const Real* value = a.value;
  constexpr int lanes = static_cast<int>(16 / sizeof(V));
  constexpr int nv = W / lanes;    // whole 16-byte vectors per block row
  constexpr int rest = W % lanes;  // remaining scalar columns
  using S = typename Simd16<V>::type;
  for (std::size_t i = begin; i < end; ++i) {
    // Two interleaved accumulators break the add-latency chain (fixed order: deterministic).
    S sum[nv + 1], sum2[nv + 1];
    V tail[rest + 1], tail2[rest + 1];
    for (int q = 0; q < nv; ++q) sum[q] = sum2[q] = S{};
    for (int c = 0; c < rest; ++c) tail[c] = tail2[c] = 0;
    int k = start[i];
    const int kEnd = start[i + 1];
    for (; k + 1 < kEnd; k += 2) {
      const V v = static_cast<V>(value[k]), v2 = static_cast<V>(value[k + 1]);
      const V* xj = x + static_cast<std::size_t>(index[k]) * W;
      const V* xj2 = x + static_cast<std::size_t>(index[k + 1]) * W;
      for (int q = 0; q < nv; ++q) {
        S t, t2;
        std::memcpy(&t, xj + q * lanes, sizeof(S));
        std::memcpy(&t2, xj2 + q * lanes, sizeof(S));
        sum[q] += v * t;
        sum2[q] += v2 * t2;
      }
      for (int c = 0; c < rest; ++c) {
        tail[c] += v * xj[nv * lanes + c];
        tail2[c] += v2 * xj2[nv * lanes + c];
      }
    }
    if (k < kEnd) {
      const V v = static_cast<V>(value[k]);
      const V* xj = x + static_cast<std::size_t>(index[k]) * W;
      for (int q = 0; q < nv; ++q) {
        S t;
        std::memcpy(&t, xj + q * lanes, sizeof(S));
        sum[q] += v * t;
      }
      for (int c = 0; c < rest; ++c) tail[c] += v * xj[nv * lanes + c];
    }
    V* yi = y + i * W;
    for (int q = 0; q < nv; ++q) {
      sum[q] += sum2[q];
      if constexpr (accumulate) {
        S t;
        std::memcpy(&t, yi + q * lanes, sizeof(S));
        sum[q] += t;
      }
      std::memcpy(yi + q * lanes, &sum[q], sizeof(S));
    }
    for (int c = 0; c < rest; ++c) {
      const V t = tail[c] + tail2[c];
      yi[nv * lanes + c] = accumulate ? yi[nv * lanes + c] + t : t;
    }
  }
}

template <int W, class Real, class V, bool accumulate = false>
inline void multiplyRows(const CsrMatrix<Real>& a, const V* x, V* y, std::size_t begin,
                         std::size_t end) {
  multiplyRows<W, Real, V, accumulate>(view(a), x, y, begin, end);
}

/// y = A x in parallel.
template <int W, class Real, class V>
void multiply(const CsrMatrix<Real>& a, const V* x, V* y) {
  parallelRanges(
      static_cast<std::size_t>(a.rows),
      [&](std::size_t b, std::size_t e) { multiplyRows<W>(a, x, y, b, e); }, 512);
}

/// y += A x in parallel.
template <int W, class Real, class V>
void multiplyAdd(const CsrMatrix<Real>& a, const V* x, V* y) {
  parallelRanges(
      static_cast<std::size_t>(a.rows),
      [&](std::size_t b, std::size_t e) { multiplyRows<W, Real, V, true>(a, x, y, b, e); }, 512);
}

/// Scratch arrays of a RowAccumulator for up to `cols` columns (one per thread, reused).
struct AccumulatorStorage {
  std::vector<int> slot;  ///< column -> position in columns, −1 when absent
  std::vector<int> columns;
  std::vector<double> sums;
};

/// Sparse accumulator: sums the values added to each column in call order. A light view on
/// AccumulatorStorage, meant to live on the stack of the row loop (so that its count stays
/// in a register).
class RowAccumulator {
 public:
  explicit RowAccumulator(AccumulatorStorage& s)
      : slot_(s.slot.data()), columns_(s.columns.data()), sums_(s.sums.data()) {}
  void add(int column, double value) {
    const int s = slot_[column];
    if (s < 0) {
      slot_[column] = count_;
      columns_[count_] = column;
      sums_[count_] = value;
      ++count_;
    } else {
      sums_[s] += value;
    }
  }
  /// Appends the row (columns in first-touch order) to (index, value) and resets.
  void flush(std::vector<int>& index, std::vector<double>& value) {
    index.insert(index.end(), columns_, columns_ + count_);
    value.insert(value.end(), sums_, sums_ + count_);
    for (int q = 0; q < count_; ++q) slot_[columns_[q]] = -1;
    count_ = 0;
  }

 private:
  int* slot_;
  int* columns_;
  double* sums_;
  int count_ = 0;
};

/// One chunk of consecutive rows built by one task.
struct RowChunk {
  std::vector<int> rowLength;
  std::vector<int> index;
  std::vector<double> value;
};
inline constexpr int kRowsPerChunk = 256;
/// Concatenates the chunks (in order) into a CSR matrix.
CsrMatrix<double> assembleChunks(int rows, int cols, std::vector<RowChunk>& chunks);
/// Per-thread accumulator storage for at least `cols` columns, reused across calls.
AccumulatorStorage& threadAccumulatorStorage(int cols);

/// Builds a CSR matrix with `rows` rows and `cols` columns in parallel: rowFn(i, acc) calls
/// acc.add(column, value) any number of times (repeated columns are summed in call order);
/// the row's columns are stored in first-touch order (not sorted). Deterministic for any
/// thread count.
template <class RowFn>
CsrMatrix<double> buildRows(int rows, int cols, RowFn&& rowFn) {
  const int chunkCount = (rows + kRowsPerChunk - 1) / kRowsPerChunk;
  std::vector<RowChunk> chunks(chunkCount);
  tbb::parallel_for(tbb::blocked_range<int>(0, chunkCount, 1),
                    [&](const tbb::blocked_range<int>& r) {
                      RowAccumulator acc(threadAccumulatorStorage(cols));
                      for (int c = r.begin(); c != r.end(); ++c) {
                        RowChunk& chunk = chunks[c];
                        const int begin = c * kRowsPerChunk;
                        const int end = std::min(rows, begin + kRowsPerChunk);
                        chunk.rowLength.reserve(end - begin);
                        for (int i = begin; i < end; ++i) {
                          const std::size_t before = chunk.index.size();
                          rowFn(i, acc);
                          acc.flush(chunk.index, chunk.value);
                          chunk.rowLength.push_back(static_cast<int>(chunk.index.size() - before));
                        }
                      }
                    });
  return assembleChunks(rows, cols, chunks);
}

/// Aᵀ (deterministic: entries of each output row keep ascending input-row order).
CsrMatrix<double> transpose(const CsrMatrix<double>& a);
/// A B, parallel over rows of A, deterministic.
CsrMatrix<double> product(const CsrMatrix<double>& a, const CsrMatrix<double>& b);

}  // namespace tfd::core::linalg
