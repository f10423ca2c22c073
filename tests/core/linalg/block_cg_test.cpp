// Batched preconditioned CG (core/linalg/block_cg.h): solves the 3-D Poisson system to the
// requested tolerance for several columns at once, the solution of a mirror-symmetric problem
// is mirror-symmetric, columns do not influence each other, and failures are errors.
#include "core/linalg/block_cg.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "tests/core/linalg/poisson_matrices.h"

namespace tfd::core::linalg {
namespace {

using testing::gridIndex;
using testing::hashUnit;
using testing::poisson3d;

double residualNorm(const CsrMatrix<double>& a, const std::vector<double>& b,
                    const std::vector<double>& x, int w, int column) {
  std::vector<double> xc(a.rows), ax(a.rows);
  for (int i = 0; i < a.rows; ++i) xc[i] = x[i * w + column];
  multiply<1>(a, xc.data(), ax.data());
  double r = 0, nb = 0;
  for (int i = 0; i < a.rows; ++i) {
    r += (b[i * w + column] - ax[i]) * (b[i * w + column] - ax[i]);
    nb += b[i * w + column] * b[i * w + column];
  }
  return std::sqrt(r / nb);
}

TEST(BlockCg, SolvesPoissonToToleranceForThreeColumns) {
  const int n = 20;
  const CsrMatrix<double> a = poisson3d(n);
  const AmgPreconditioner m(a);
  constexpr int W = 3;
  // Known solutions, right-hand sides from them.
  std::vector<double> exact(a.rows * W), b(a.rows * W), x(a.rows * W, 0.0);
  for (std::size_t i = 0; i < exact.size(); ++i) exact[i] = hashUnit(i);
  multiply<W>(a, exact.data(), b.data());
  CgOptions o;
  o.tolerance = 1e-10;
  const CgResult r = blockPcg<W>(a, b.data(), x.data(), m, o, Progress{});
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.relativeResidual, 1e-10);
  EXPECT_LT(r.iterations, 40) << "multigrid keeps CG iterations low";
  for (int c = 0; c < W; ++c) {
    EXPECT_LE(residualNorm(a, b, x, W, c), 1e-10) << c;
    double err = 0, norm = 0;
    for (int i = 0; i < a.rows; ++i) {
      err = std::max(err, std::abs(x[i * W + c] - exact[i * W + c]));
      norm = std::max(norm, std::abs(exact[i * W + c]));
    }
    // κ(A) ≈ 4n²/π² ≈ 160, so the error is at most ~κ times the residual.
    EXPECT_LT(err / norm, 1e-7) << c;
  }
}

TEST(BlockCg, MirrorSymmetricProblemHasAMirrorSymmetricSolution) {
  // A point load at the centre of the grid: the solution is symmetric under i -> n−1−i (and the
  // other axes), positive (discrete maximum principle) and largest at the load.
  const int n = 21, c = n / 2;
  const CsrMatrix<double> a = poisson3d(n);
  const AmgPreconditioner m(a);
  std::vector<double> b(a.rows, 0.0), x(a.rows, 0.0);
  b[gridIndex(n, c, c, c)] = 1;
  CgOptions o;
  o.tolerance = 1e-12;
  blockPcg<1>(a, b.data(), x.data(), m, o, Progress{});
  double asym = 0, smallest = 1e300, largest = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double v = x[gridIndex(n, i, j, k)];
        asym = std::max(asym, std::abs(v - x[gridIndex(n, n - 1 - i, j, k)]));
        asym = std::max(asym, std::abs(v - x[gridIndex(n, i, n - 1 - j, k)]));
        asym = std::max(asym, std::abs(v - x[gridIndex(n, j, i, k)]));  // diagonal mirror
        asym = std::max(asym, std::abs(v - x[gridIndex(n, i, k, j)]));
        smallest = std::min(smallest, v), largest = std::max(largest, v);
      }
  EXPECT_LT(asym, 1e-10 * largest);
  EXPECT_GT(smallest, 0);
  EXPECT_EQ(largest, x[gridIndex(n, c, c, c)]);
}

TEST(BlockCg, ColumnsAreIndependent) {
  // The second column solved alone or beside another gives the same solution.
  const CsrMatrix<double> a = poisson3d(14);
  const AmgPreconditioner m(a);
  std::vector<double> b2(a.rows * 2), x2(a.rows * 2, 0.0), b1(a.rows), x1(a.rows, 0.0);
  for (int i = 0; i < a.rows; ++i) {
    b2[2 * i] = 1.0;  // a smooth column
    b2[2 * i + 1] = b1[i] = hashUnit(i);
  }
  CgOptions o;
  o.tolerance = 1e-11;
  blockPcg<2>(a, b2.data(), x2.data(), m, o, Progress{});
  blockPcg<1>(a, b1.data(), x1.data(), m, o, Progress{});
  double d = 0, s = 0;
  for (int i = 0; i < a.rows; ++i)
    d = std::max(d, std::abs(x2[2 * i + 1] - x1[i])), s = std::max(s, std::abs(x1[i]));
  EXPECT_LT(d, 1e-9 * s);
}

TEST(BlockCg, BitwiseEqualForOneAndTwoThreads) {
  const CsrMatrix<double> a = poisson3d(22);
  std::vector<double> b(a.rows * 2);
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = hashUnit(i);
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    const AmgPreconditioner m(a);
    std::vector<double> x(b.size(), 0.0);
    const CgResult r = blockPcg<2>(a, b.data(), x.data(), m, CgOptions{}, Progress{});
    x.push_back(r.iterations);
    return x;
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(BlockCg, TooFewIterationsAndCancellationAreErrors) {
  const CsrMatrix<double> a = poisson3d(16);
  const AmgPreconditioner m(a);
  std::vector<double> b(a.rows), x(a.rows, 0.0);
  for (int i = 0; i < a.rows; ++i) b[i] = hashUnit(i);
  CgOptions o;
  o.tolerance = 1e-14;
  o.maxIterations = 2;
  try {
    blockPcg<1>(a, b.data(), x.data(), m, o, Progress{});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("residual"), std::string::npos) << e.what();
  }
  std::atomic<bool> cancel{true};
  std::fill(x.begin(), x.end(), 0.0);
  EXPECT_THROW(blockPcg<1>(a, b.data(), x.data(), m, CgOptions{}, Progress({}, &cancel)),
               Cancelled);
}

}  // namespace
}  // namespace tfd::core::linalg
