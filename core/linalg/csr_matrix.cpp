#include "core/linalg/csr_matrix.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <memory>
#include <numeric>

namespace tfd::core::linalg {

AccumulatorStorage& threadAccumulatorStorage(int cols) {
  // Slots are always reset to −1 by flush, so the storage can be reused across matrices.
  static tbb::enumerable_thread_specific<AccumulatorStorage> storage;
  AccumulatorStorage& local = storage.local();
  if (static_cast<int>(local.slot.size()) < cols) {
    local.slot.assign(cols, -1);
    local.columns.resize(cols);
    local.sums.resize(cols);
  }
  return local;
}

CsrMatrix<double> assembleChunks(int rows, int cols, std::vector<RowChunk>& chunks) {
  const int chunkCount = static_cast<int>(chunks.size());
  CsrMatrix<double> out;
  out.rows = rows;
  out.cols = cols;
  out.start.assign(rows + 1, 0);
  std::vector<std::size_t> chunkOffset(chunkCount + 1, 0);
  int row = 0;
  for (int c = 0; c < chunkCount; ++c) {
    chunkOffset[c + 1] = chunkOffset[c] + chunks[c].index.size();
    for (int len : chunks[c].rowLength) {
      out.start[row + 1] = out.start[row] + len;
      ++row;
    }
  }
  out.index.resize(chunkOffset[chunkCount]);
  out.value.resize(chunkOffset[chunkCount]);
  tbb::parallel_for(0, chunkCount, [&](int c) {
    std::copy(chunks[c].index.begin(), chunks[c].index.end(), out.index.begin() + chunkOffset[c]);
    std::copy(chunks[c].value.begin(), chunks[c].value.end(), out.value.begin() + chunkOffset[c]);
    chunks[c] = RowChunk{};
  });
  return out;
}

CsrMatrix<double> transpose(const CsrMatrix<double>& a) {
  CsrMatrix<double> t;
  t.rows = a.cols;
  t.cols = a.rows;
  t.start.assign(a.cols + 1, 0);
  for (int j : a.index) ++t.start[j + 1];
  for (int j = 0; j < a.cols; ++j) t.start[j + 1] += t.start[j];
  t.index.resize(a.nonZeros());
  t.value.resize(a.nonZeros());
  std::vector<int> next(t.start.begin(), t.start.end() - 1);
  for (int i = 0; i < a.rows; ++i)
    for (int k = a.start[i]; k < a.start[i + 1]; ++k) {
      const int slot = next[a.index[k]]++;
      t.index[slot] = i;
      t.value[slot] = a.value[k];
    }
  return t;
}

CsrMatrix<double> product(const CsrMatrix<double>& a, const CsrMatrix<double>& b) {
  return buildRows(a.rows, b.cols, [&](int i, RowAccumulator& acc) {
    for (int k = a.start[i]; k < a.start[i + 1]; ++k) {
      const int j = a.index[k];
      const double v = a.value[k];
      for (int m = b.start[j]; m < b.start[j + 1]; ++m) acc.add(b.index[m], v * b.value[m]);
    }
  });
}

}  // namespace tfd::core::linalg
