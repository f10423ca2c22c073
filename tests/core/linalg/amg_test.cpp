// Smoothed-aggregation multigrid (core/linalg/amg.h) on the 3-D Poisson matrix: the hierarchy
// coarsens, the V-cycle is a symmetric positive definite operator (what CG needs), it reduces
// the error much better than the Jacobi smoother alone would, and an input that is not positive
// definite is refused.
#include "core/linalg/amg.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/error.h"
#include "tests/core/linalg/poisson_matrices.h"

namespace tfd::core::linalg {
namespace {

using testing::hashUnit;
using testing::poisson3d;

std::vector<double> applyOnce(const AmgPreconditioner& m, const std::vector<double>& r) {
  std::vector<double> z(r.size());
  auto ws = m.makeWorkspace(1);
  m.apply<1>(r.data(), z.data(), *ws);
  return z;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

TEST(Amg, HierarchyCoarsensToADenseLevel) {
  const CsrMatrix<double> a = poisson3d(24);  // 13824 unknowns
  const AmgPreconditioner m(a);
  const auto& levels = m.levels();
  ASSERT_GE(levels.size(), 2u);
  EXPECT_EQ(levels[0].rows, a.rows);
  for (std::size_t l = 1; l < levels.size(); ++l) EXPECT_LT(levels[l].rows * 4, levels[l - 1].rows);
  EXPECT_LE(levels.back().rows, AmgOptions{}.coarsestSize);
  EXPECT_GT(m.operatorComplexity(), 1.0);
  EXPECT_LT(m.operatorComplexity(), 2.0);
  // ρ(D⁻¹A) of the 7-point Laplacian is below 2 (eigenvalues 1 − cos terms / 3 ∈ (0, 2)); the
  // estimate with its margin lies just above the true value 1 + cos(π/25) ≈ 1.992.
  EXPECT_GT(levels[0].lambdaMax, 1.95);
  EXPECT_LT(levels[0].lambdaMax, 2.5);
  EXPECT_NEAR(estimateLambdaMax(a, 30), 1 + std::cos(M_PI / 25), 0.02);
}

TEST(Amg, VCycleIsSymmetricPositiveDefinite) {
  const CsrMatrix<double> a = poisson3d(16);
  for (const bool single : {true, false}) {
    AmgOptions o;
    o.singlePrecision = single;
    const AmgPreconditioner m(a, o);
    std::vector<double> r(a.rows), s(a.rows);
    for (int i = 0; i < a.rows; ++i) r[i] = hashUnit(i), s[i] = hashUnit(i + 99991);
    const auto mr = applyOnce(m, r), ms = applyOnce(m, s);
    // ⟨M⁻¹r, s⟩ = ⟨r, M⁻¹s⟩ (to the cycle's precision) and ⟨M⁻¹r, r⟩ > 0.
    const double tol = single ? 1e-5 : 1e-11;
    EXPECT_NEAR(dot(mr, s), dot(r, ms), tol * std::sqrt(dot(mr, mr) * dot(s, s))) << single;
    EXPECT_GT(dot(mr, r), 0) << single;
    EXPECT_GT(dot(ms, s), 0) << single;
  }
}

TEST(Amg, OneCycleReducesTheErrorOfASmoothMode) {
  // The smoothest mode is what Jacobi-type smoothing cannot touch; the coarse levels must.
  const int n = 20;
  const CsrMatrix<double> a = poisson3d(n);
  const AmgPreconditioner m(a);
  std::vector<double> x(a.rows), b(a.rows);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        x[testing::gridIndex(n, i, j, k)] = std::sin(M_PI * (i + 1) / (n + 1)) *
                                            std::sin(M_PI * (j + 1) / (n + 1)) *
                                            std::sin(M_PI * (k + 1) / (n + 1));
  multiply<1>(a, x.data(), b.data());
  const auto z = applyOnce(m, b);  // one preconditioner application: z ≈ x
  std::vector<double> e(a.rows);
  for (int i = 0; i < a.rows; ++i) e[i] = z[i] - x[i];
  EXPECT_LT(std::sqrt(dot(e, e) / dot(x, x)), 0.5);
}

TEST(Amg, BitwiseEqualForOneAndTwoThreads) {
  const CsrMatrix<double> a = poisson3d(22);
  std::vector<double> r(a.rows);
  for (int i = 0; i < a.rows; ++i) r[i] = hashUnit(i);
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    const AmgPreconditioner m(a);
    return applyOnce(m, r);
  };
  EXPECT_EQ(run(1), run(2));
}

/// z = M⁻¹ r for W interleaved columns.
template <int W>
std::vector<double> applyColumns(const AmgPreconditioner& m, const std::vector<double>& r) {
  std::vector<double> z(r.size());
  auto ws = m.makeWorkspace(W);
  m.apply<W>(r.data(), z.data(), *ws);
  return z;
}

template <int W>
void expectColumnsOfOneCycle(const AmgPreconditioner& m, int rows) {
  std::vector<double> r(static_cast<std::size_t>(rows) * W);
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = hashUnit(k + 7 * W);
  const std::vector<double> z = applyColumns<W>(m, r);
  for (int c = 0; c < W; ++c) {
    std::vector<double> column(rows);
    for (int i = 0; i < rows; ++i) column[i] = r[i * W + c];
    const std::vector<double> alone = applyOnce(m, column);
    int differing = 0;
    for (int i = 0; i < rows; ++i) differing += z[i * W + c] != alone[i];
    EXPECT_EQ(differing, 0) << "column " << c << " of " << W;
  }
}

TEST(Amg, EveryColumnOfABlockIsTheOneColumnCycleBitForBit) {
  // The float cycle carries 3 columns as 4 (a zero column beside them, for whole-register
  // gathers): each column must still see exactly the operations of a cycle of its own, for
  // every width and in both precisions. A stride or a padding column mixed into the
  // others fails this.
  const CsrMatrix<double> a = poisson3d(22);  // two levels and a dense coarsest one
  for (const bool single : {true, false}) {
    AmgOptions o;
    o.singlePrecision = single;
    const AmgPreconditioner m(a, o);
    ASSERT_GE(m.levels().size(), 3u);
    expectColumnsOfOneCycle<2>(m, a.rows);
    expectColumnsOfOneCycle<3>(m, a.rows);
    expectColumnsOfOneCycle<4>(m, a.rows);
    expectColumnsOfOneCycle<5>(m, a.rows);
    expectColumnsOfOneCycle<6>(m, a.rows);
  }
}

TEST(Amg, MatrixThatIsNotPositiveDefiniteIsRefused) {
  // Tridiagonal (−1, 1, −1): symmetric with a positive diagonal, but eigenvalues 1 − 2cos(kπ/51)
  // down to −1. Small enough for the dense coarsest level, whose Cholesky must fail.
  CsrMatrix<double> a;
  const int n = 50;
  a.rows = a.cols = n;
  a.start.assign(1, 0);
  for (int i = 0; i < n; ++i) {
    if (i > 0) a.index.push_back(i - 1), a.value.push_back(-1);
    a.index.push_back(i), a.value.push_back(1);
    if (i < n - 1) a.index.push_back(i + 1), a.value.push_back(-1);
    a.start.push_back(static_cast<int>(a.index.size()));
  }
  EXPECT_THROW(AmgPreconditioner m(a), Error);
}

TEST(Amg, SinglePrecisionSharesTheFineMatrixStructure) {
  // The double-precision hierarchy references the fine matrix; the float one copies only its
  // values (4 bytes an entry), not its row starts and column indices, so with its float
  // prolongators and coarse levels it holds less. A full float copy of the fine matrix (8
  // bytes an entry) made it hold more: 2.26 MB against 2.14 MB here.
  const CsrMatrix<double> a = poisson3d(24);
  AmgOptions twice;
  twice.singlePrecision = false;
  EXPECT_LT(AmgPreconditioner(a).bytes(), AmgPreconditioner(a, twice).bytes());
}

}  // namespace
}  // namespace tfd::core::linalg
