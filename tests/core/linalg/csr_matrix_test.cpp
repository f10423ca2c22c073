// CSR kernels (core/linalg/csr_matrix.h): products with W interleaved columns, transpose,
// sparse-sparse product and row building, each against a dense reference; 1 vs 2 threads.
#include "core/linalg/csr_matrix.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "tests/core/linalg/poisson_matrices.h"

namespace tfd::core::linalg {
namespace {

using testing::dense;
using testing::hashUnit;
using testing::randomSparse;

template <int W>
void checkMultiply(const CsrMatrix<double>& a) {
  std::vector<double> x(static_cast<std::size_t>(a.cols) * W),
      y(static_cast<std::size_t>(a.rows) * W);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = hashUnit(i + 17);
  multiply<W>(a, x.data(), y.data());
  const Eigen::MatrixXd d = dense(a);
  Eigen::MatrixXd xm(a.cols, W);
  for (int i = 0; i < a.cols; ++i)
    for (int c = 0; c < W; ++c) xm(i, c) = x[i * W + c];
  const Eigen::MatrixXd ref = d * xm;
  double worst = 0;
  for (int i = 0; i < a.rows; ++i)
    for (int c = 0; c < W; ++c) worst = std::max(worst, std::abs(y[i * W + c] - ref(i, c)));
  EXPECT_LT(worst, 1e-12) << "W = " << W;
  // y += A x doubles it.
  multiplyAdd<W>(a, x.data(), y.data());
  for (int i = 0; i < a.rows; ++i)
    for (int c = 0; c < W; ++c) ASSERT_NEAR(y[i * W + c], 2 * ref(i, c), 1e-12);
}

TEST(CsrMatrix, ProductsWithInterleavedColumnsMatchDense) {
  // Rows of odd and even lengths, more rows than one parallel grain.
  const CsrMatrix<double> a = randomSparse(1500, 700, 9, 3);
  checkMultiply<1>(a);
  checkMultiply<2>(a);
  checkMultiply<3>(a);
  checkMultiply<5>(a);
  checkMultiply<6>(a);
}

TEST(CsrMatrix, SinglePrecisionCopyMultipliesInDoubleSums) {
  const CsrMatrix<double> a = randomSparse(300, 300, 7, 4);
  const CsrMatrix<float> f = convert<float>(a);
  EXPECT_EQ(f.index, a.index);
  std::vector<double> x(300), y(300), yd(300);
  for (int i = 0; i < 300; ++i) x[i] = hashUnit(i);
  multiply<1>(f, x.data(), y.data());
  multiply<1>(a, x.data(), yd.data());
  for (int i = 0; i < 300; ++i) EXPECT_NEAR(y[i], yd[i], 1e-6);
}

TEST(CsrMatrix, TransposeMatchesDenseAndKeepsRowOrder) {
  const CsrMatrix<double> a = randomSparse(400, 250, 6, 5);
  const CsrMatrix<double> t = transpose(a);
  EXPECT_EQ(t.rows, a.cols);
  EXPECT_EQ(t.cols, a.rows);
  EXPECT_EQ(t.nonZeros(), a.nonZeros());
  EXPECT_EQ(dense(t), dense(a).transpose());
  for (int i = 0; i < t.rows; ++i)
    for (int m = t.start[i] + 1; m < t.start[i + 1]; ++m) ASSERT_LT(t.index[m - 1], t.index[m]);
  // Twice is the identity, entry for entry.
  const CsrMatrix<double> tt = transpose(t);
  EXPECT_EQ(tt.start, a.start);
  EXPECT_EQ(tt.index, a.index);
  EXPECT_EQ(tt.value, a.value);
}

TEST(CsrMatrix, SparseProductMatchesDense) {
  const CsrMatrix<double> a = randomSparse(350, 300, 8, 6), b = randomSparse(300, 280, 5, 7);
  const CsrMatrix<double> c = product(a, b);
  EXPECT_EQ(c.rows, 350);
  EXPECT_EQ(c.cols, 280);
  EXPECT_LT((dense(c) - dense(a) * dense(b)).cwiseAbs().maxCoeff(), 1e-12);
  // AᵀA is symmetric (the Galerkin products of the multigrid rely on it).
  const Eigen::MatrixXd ata = dense(product(transpose(a), a));
  EXPECT_LT((ata - ata.transpose()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(CsrMatrix, BuildRowsSumsRepeatedColumnsInFirstTouchOrder) {
  const int rows = 1000, cols = 60;  // several chunks of kRowsPerChunk rows
  const CsrMatrix<double> a = buildRows(rows, cols, [](int i, RowAccumulator& acc) {
    acc.add((i * 7) % cols, 1.0);
    acc.add((i * 3) % cols, 2.0);
    acc.add((i * 7) % cols, 0.5);  // same column as the first: summed
  });
  ASSERT_EQ(a.rows, rows);
  for (int i = 0; i < rows; ++i) {
    const int c7 = (i * 7) % cols, c3 = (i * 3) % cols;
    if (c7 == c3) {
      ASSERT_EQ(a.start[i + 1] - a.start[i], 1);
      EXPECT_EQ(a.value[a.start[i]], 3.5);
    } else {
      ASSERT_EQ(a.start[i + 1] - a.start[i], 2);
      EXPECT_EQ(a.index[a.start[i]], c7);
      EXPECT_EQ(a.value[a.start[i]], 1.5);
      EXPECT_EQ(a.index[a.start[i] + 1], c3);
      EXPECT_EQ(a.value[a.start[i] + 1], 2.0);
    }
  }
}

TEST(CsrMatrix, BitwiseEqualForOneAndTwoThreads) {
  const CsrMatrix<double> a = randomSparse(3000, 3000, 12, 8);
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    std::vector<double> x(3000 * 3), y(3000 * 3);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = hashUnit(i);
    multiply<3>(a, x.data(), y.data());
    const CsrMatrix<double> p = product(transpose(a), a);
    return std::make_pair(y, p.value);
  };
  EXPECT_EQ(run(1), run(2));
}

}  // namespace
}  // namespace tfd::core::linalg
