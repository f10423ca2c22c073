#include "core/linalg/amg.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.h"

namespace tfd::core::linalg {

namespace {

std::vector<double> diagonalOf(const CsrMatrix<double>& a) {
  std::vector<double> d(a.rows, 0.0);
  parallelRanges(a.rows, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      for (int k = a.start[i]; k < a.start[i + 1]; ++k)
        if (a.index[k] == static_cast<int>(i)) d[i] = a.value[k];
  });
  return d;
}

/// Greedy aggregation (three passes, in row order). Returns the aggregate of each row (−1 for
/// rows without strong connections, which only the smoother treats) and the count.
std::vector<int> aggregate(const CsrMatrix<double>& a, const std::vector<double>& diag,
                           double theta, int& count, std::vector<unsigned char>& strong) {
  const int n = a.rows;
  // Strong connections, one flag per entry: a_ij² ≥ θ² a_ii a_jj.
  strong.assign(a.nonZeros(), 0);
  const double theta2 = theta * theta;
  parallelRanges(n, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i)
      for (int k = a.start[i]; k < a.start[i + 1]; ++k) {
        const int j = a.index[k];
        if (j != static_cast<int>(i) &&
            a.value[k] * a.value[k] >= theta2 * std::abs(diag[i] * diag[j]))
          strong[k] = 1;
      }
  });
  std::vector<int> agg(n, -1);
  count = 0;
  // Pass 1: a row whose strong neighbours are all free seeds an aggregate with them.
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    bool hasStrong = false, allFree = true;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k)
      if (strong[k]) {
        hasStrong = true;
        if (agg[a.index[k]] >= 0) {
          allFree = false;
          break;
        }
      }
    if (!hasStrong || !allFree) continue;
    agg[i] = count;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k)
      if (strong[k]) agg[a.index[k]] = count;
    ++count;
  }
  // Pass 2: remaining rows join the aggregate of their strongest aggregated neighbour.
  std::vector<int> pass2(agg);
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    double best = 0;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k)
      if (strong[k] && agg[a.index[k]] >= 0 && std::abs(a.value[k]) > best) {
        best = std::abs(a.value[k]);
        pass2[i] = agg[a.index[k]];
      }
  }
  agg.swap(pass2);
  // Pass 3: leftovers with strong connections form aggregates with their free neighbours.
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    bool hasStrong = false;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k)
      if (strong[k]) hasStrong = true;
    if (!hasStrong) continue;
    agg[i] = count;
    for (int k = a.start[i]; k < a.start[i + 1]; ++k)
      if (strong[k] && agg[a.index[k]] < 0) agg[a.index[k]] = count;
    ++count;
  }
  return agg;
}

/// Deterministic pseudo-random value in [−1, 1] for index i (splitmix64).
double hashUnit(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

template <class Real>
struct Level {
  CsrMatrix<Real> ownedA;  ///< levels below the finest
  /// The finest level in float: the fine matrix's values (its row starts and column indices
  /// are the fine matrix's own, not copied).
  std::vector<Real> fineValues;
  CsrView<Real> a;    ///< the level's matrix (set by finishViews)
  CsrMatrix<Real> p;  ///< rows × next rows
  CsrMatrix<Real> r;  ///< pᵀ
  std::vector<Real> invDiag;
  double lambdaMax = 2;
};

template <class Real>
struct Hierarchy {
  std::vector<Level<Real>> levels;  ///< all but a dense coarsest level
  Eigen::LLT<Eigen::MatrixXd> coarse;
  int coarseRows = 0;  ///< 0: no dense level, the last level is smoother-only
};

/// Largest matrix factorised densely at the bottom of the hierarchy.
constexpr int kDenseLimit = 2000;

}  // namespace

double estimateLambdaMax(const CsrMatrix<double>& a, int iterations) {
  // Lanczos on B = D^{-1/2} A D^{-1/2} (same spectrum as D⁻¹A): the largest Ritz value of the
  // tridiagonal matrix converges to λmax much faster than power iteration does.
  const std::size_t n = static_cast<std::size_t>(a.rows);
  if (n == 0) return 1;
  const std::vector<double> diag = diagonalOf(a);
  std::vector<double> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = diag[i] > 0 ? 1.0 / std::sqrt(diag[i]) : 0.0;
  std::vector<double> v(n), vOld(n, 0.0), w(n), t(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = hashUnit(i);
  const double norm0 = std::sqrt(
      deterministicSums<1>(n, [&](std::size_t b, std::size_t e, std::array<double, 1>& acc) {
        for (std::size_t i = b; i < e; ++i) acc[0] += v[i] * v[i];
      })[0]);
  for (double& x : v) x /= norm0;
  std::vector<double> alpha, beta;
  double betaOld = 0;
  const int steps = std::max(1, std::min<int>(iterations, static_cast<int>(n)));
  for (int j = 0; j < steps; ++j) {
    parallelRanges(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) t[i] = s[i] * v[i];
    });
    multiply<1>(a, t.data(), w.data());
    const double al =
        deterministicSums<1>(n, [&](std::size_t b, std::size_t e, std::array<double, 1>& acc) {
          for (std::size_t i = b; i < e; ++i) {
            w[i] = s[i] * w[i] - betaOld * vOld[i];
            acc[0] += w[i] * v[i];
          }
        })[0];
    alpha.push_back(al);
    const double be = std::sqrt(
        deterministicSums<1>(n, [&](std::size_t b, std::size_t e, std::array<double, 1>& acc) {
          for (std::size_t i = b; i < e; ++i) {
            w[i] -= al * v[i];
            acc[0] += w[i] * w[i];
          }
        })[0]);
    if (!(be > 1e-12 * std::abs(al)) || j + 1 == steps) break;
    beta.push_back(be);
    parallelRanges(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        vOld[i] = v[i];
        v[i] = w[i] / be;
      }
    });
    betaOld = be;
  }
  const int m = static_cast<int>(alpha.size());
  Eigen::MatrixXd tri = Eigen::MatrixXd::Zero(m, m);
  for (int i = 0; i < m; ++i) {
    tri(i, i) = alpha[i];
    if (i + 1 < m) tri(i, i + 1) = tri(i + 1, i) = beta[i];
  }
  const double lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(tri).eigenvalues().maxCoeff();
  return lambda > 0 ? lambda : 1;
}

struct AmgPreconditioner::Impl {
  AmgOptions options;
  std::vector<AmgLevelInfo> info;
  Hierarchy<float> single;
  Hierarchy<double> twice;
};

namespace {

/// Columns a float cycle carries for W right-hand sides: 3 are carried as 4, one 16-byte
/// vector, so that each gather of a block row in the product kernels is one whole-register
/// load and multiply-add instead of three scalar ones (multiplyRows): a third less time in
/// the cycles of the 1M torus's angle solve (163K rows; bench/RESULTS.md). 5 and 6 stay (as 8
/// they were not faster in propagate_bench). The extra column holds zeros throughout (a zero
/// right-hand side stays zero through every level) and each real column sees the same
/// operations in the same order: the results are bitwise those of W columns.
constexpr int paddedWidth(int w) { return w == 3 ? 4 : w; }

}  // namespace

class AmgPreconditioner::Workspace {
 public:
  int width = 0;
  // Per level l ≥ 1: right-hand side and solution; per level: residual and direction.
  std::vector<std::vector<float>> bf, xf, rf, df;
  std::vector<std::vector<double>> bd, xd, rd, dd;
  std::vector<float> fineB, fineX;
  Eigen::MatrixXd coarseB;
};

namespace {

/// A level's matrix `a` (the fine matrix at level 0, else `current`, which it may take):
/// the finest is referenced (in float, only its values are copied), the others owned.
template <class Real>
void keepMatrix(Level<Real>& lv, int level, const CsrMatrix<double>& a,
                CsrMatrix<double>& current) {
  if constexpr (std::is_same_v<Real, double>) {
    if (level > 0) lv.ownedA = std::move(current);
  } else if (level == 0) {
    lv.fineValues.assign(a.value.begin(), a.value.end());
  } else {
    lv.ownedA = convert<float>(a);
  }
}

template <class Real>
void buildHierarchy(const CsrMatrix<double>& fine, const AmgOptions& options, Hierarchy<Real>& h,
                    std::vector<AmgLevelInfo>& info) {
  CsrMatrix<double> current;  // the level's matrix in double (empty for level 0: use `fine`)
  const CsrMatrix<double>* a = &fine;
  for (int level = 0;; ++level) {
    AmgLevelInfo li;
    li.rows = a->rows;
    li.nonZeros = a->nonZeros();
    const bool last = a->rows <= options.coarsestSize || level + 1 >= options.maxLevels;
    std::vector<int> agg;
    std::vector<unsigned char> strong;
    int coarseCount = 0;
    const std::vector<double> diag = diagonalOf(*a);
    for (int i = 0; i < a->rows; ++i)
      if (!(diag[i] > 0))
        throw Error("multigrid set-up: row " + std::to_string(i) + " of level " +
                    std::to_string(level) + " has a non-positive diagonal");
    if (!last) {
      agg = aggregate(*a, diag, options.strengthThreshold, coarseCount, strong);
      if (coarseCount == 0 || coarseCount > a->rows * 0.85) coarseCount = -1;  // no progress
    }
    if ((last || coarseCount < 0) && a->rows > kDenseLimit) {
      // Cannot coarsen further (e.g. free vertices with no free neighbours: a diagonal
      // matrix) and too big for a dense factorisation: the last level is solved
      // approximately by a longer Chebyshev polynomial (still symmetric positive definite).
      Level<Real> lv;
      lv.lambdaMax = level == 0 && options.fineLambdaMax > 0 ? options.fineLambdaMax
                                                             : estimateLambdaMax(*a, 12) * 1.1;
      li.lambdaMax = lv.lambdaMax;
      keepMatrix(lv, level, *a, current);
      lv.invDiag.resize(diag.size());
      for (std::size_t i = 0; i < diag.size(); ++i)
        lv.invDiag[i] = static_cast<Real>(1.0 / diag[i]);
      h.levels.push_back(std::move(lv));
      h.coarseRows = 0;
      info.push_back(li);
      return;
    }
    if (last || coarseCount < 0) {
      // Dense Cholesky of the coarsest matrix.
      Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(a->rows, a->rows);
      for (int i = 0; i < a->rows; ++i)
        for (int k = a->start[i]; k < a->start[i + 1]; ++k) dense(i, a->index[k]) = a->value[k];
      dense = 0.5 * (dense + dense.transpose()).eval();
      h.coarse.compute(dense);
      if (h.coarse.info() != Eigen::Success)
        throw Error("multigrid set-up: the coarsest matrix (" + std::to_string(a->rows) +
                    " rows) is not positive definite; the system is singular");
      h.coarseRows = a->rows;
      info.push_back(li);
      return;
    }
    Level<Real> lv;
    // Lanczos approaches λmax from below; the 10 % margin keeps the Chebyshev smoother
    // stable (it tolerates a few percent of underestimate on top of that).
    lv.lambdaMax = level == 0 && options.fineLambdaMax > 0 ? options.fineLambdaMax
                                                           : estimateLambdaMax(*a, 12) * 1.1;
    li.lambdaMax = lv.lambdaMax;
    // Smoothed prolongator P = (I − ω D⁻¹A) P₀.
    const double omega = 4.0 / (3.0 * lv.lambdaMax / 1.1);  // ω = 4 / (3 ρ)
    // Filtered matrix (weak entries lumped into the diagonal, so constants stay in its null
    // space) keeps the prolongator sparse.
    CsrMatrix<double> p = buildRows(a->rows, coarseCount, [&](int i, RowAccumulator& acc) {
      double lumped = diag[i];
      for (int k = a->start[i]; k < a->start[i + 1]; ++k)
        if (!strong[k] && a->index[k] != i) lumped += a->value[k];
      const double scale = -omega / diag[i];
      if (agg[i] >= 0) acc.add(agg[i], 1.0 + scale * lumped);
      for (int k = a->start[i]; k < a->start[i + 1]; ++k) {
        const int j = a->index[k];
        if (strong[k] && agg[j] >= 0) acc.add(agg[j], scale * a->value[k]);
      }
    });
    CsrMatrix<double> r = transpose(p);
    // Galerkin coarse matrix RAP. Its rounding-level asymmetry is harmless: the coarsest
    // dense factorisation uses the symmetric part, and the float cycle perturbs far more.
    CsrMatrix<double> coarse = product(r, product(*a, p));
    keepMatrix(lv, level, *a, current);
    if constexpr (std::is_same_v<Real, double>) {
      lv.p = std::move(p);
      lv.r = std::move(r);
    } else {
      lv.p = convert<float>(p);
      lv.r = convert<float>(r);
    }
    lv.invDiag.resize(diag.size());
    for (std::size_t i = 0; i < diag.size(); ++i) lv.invDiag[i] = static_cast<Real>(1.0 / diag[i]);
    h.levels.push_back(std::move(lv));
    info.push_back(li);
    current = std::move(coarse);
    a = &current;
  }
}

template <class Real>
void finishViews(Hierarchy<Real>& h, const CsrMatrix<double>& fine) {
  for (std::size_t level = 0; level < h.levels.size(); ++level) {
    Level<Real>& lv = h.levels[level];
    if (level > 0) {
      lv.a = view(lv.ownedA);
    } else if constexpr (std::is_same_v<Real, double>) {
      lv.a = view(fine);
    } else {
      lv.a = {fine.rows, fine.start.data(), fine.index.data(), lv.fineValues.data()};
    }
  }
}

/// Chebyshev smoothing of A x = b (x updated in place; zeroInitial means x = 0 on entry).
template <int W, class Real>
void chebyshev(const Level<Real>& lv, int degree, double ratio, const Real* b, Real* x, Real* r,
               Real* d, bool zeroInitial) {
  const std::size_t n = static_cast<std::size_t>(lv.a.rows);
  const double lmax = lv.lambdaMax, lmin = lmax / ratio;
  const double theta = 0.5 * (lmax + lmin), delta = 0.5 * (lmax - lmin);
  const double sigma = theta / delta;
  double rho = 1.0 / sigma;
  const Real* invD = lv.invDiag.data();
  const Real* rr = b;  // residual source
  if (!zeroInitial) {
    const CsrView<Real>& a = lv.a;
    parallelRanges(
        n,
        [&](std::size_t bg, std::size_t e) {
          multiplyRows<W>(a, x, r, bg, e);
          for (std::size_t i = bg * W; i < e * W; ++i) r[i] = b[i] - r[i];
        },
        512);
    rr = r;
  }
  const Real first = static_cast<Real>(1.0 / theta);
  parallelRanges(n, [&](std::size_t bg, std::size_t e) {
    Real* __restrict dd = d;
    Real* __restrict xx = x;
    const Real* __restrict rv = rr;
    for (std::size_t i = bg; i < e; ++i) {
      const Real s = first * invD[i];
      if (zeroInitial) {
        for (int c = 0; c < W; ++c) xx[i * W + c] = dd[i * W + c] = s * rv[i * W + c];
      } else {
        for (int c = 0; c < W; ++c) {
          dd[i * W + c] = s * rv[i * W + c];
          xx[i * W + c] += dd[i * W + c];
        }
      }
    }
  });
  for (int step = 1; step < degree; ++step) {
    const CsrView<Real>& a = lv.a;
    parallelRanges(
        n,
        [&](std::size_t bg, std::size_t e) {
          multiplyRows<W>(a, x, r, bg, e);
          for (std::size_t i = bg * W; i < e * W; ++i) r[i] = b[i] - r[i];
        },
        512);
    const double rhoNew = 1.0 / (2.0 * sigma - rho);
    const Real c1 = static_cast<Real>(rhoNew * rho), c2 = static_cast<Real>(2.0 * rhoNew / delta);
    rho = rhoNew;
    parallelRanges(n, [&](std::size_t bg, std::size_t e) {
      Real* __restrict dd = d;
      Real* __restrict xx = x;
      const Real* __restrict rv = r;
      for (std::size_t i = bg; i < e; ++i) {
        const Real s = c2 * invD[i];
        for (int c = 0; c < W; ++c) {
          const std::size_t k = i * W + c;
          dd[k] = c1 * dd[k] + s * rv[k];
          xx[k] += dd[k];
        }
      }
    });
  }
}

}  // namespace

AmgPreconditioner::AmgPreconditioner(const CsrMatrix<double>& a, const AmgOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  if (a.rows != a.cols) throw Error("multigrid set-up: the matrix is not square");
  if (a.rows == 0) throw Error("multigrid set-up: empty matrix");
  if (impl_->options.singlePrecision) {
    buildHierarchy(a, impl_->options, impl_->single, impl_->info);
    finishViews(impl_->single, a);
  } else {
    buildHierarchy(a, impl_->options, impl_->twice, impl_->info);
    finishViews(impl_->twice, a);
  }
}

AmgPreconditioner::~AmgPreconditioner() = default;
AmgPreconditioner::AmgPreconditioner(AmgPreconditioner&&) noexcept = default;
AmgPreconditioner& AmgPreconditioner::operator=(AmgPreconditioner&&) noexcept = default;

const std::vector<AmgLevelInfo>& AmgPreconditioner::levels() const { return impl_->info; }

namespace {
template <class Real>
std::size_t hierarchyBytes(const Hierarchy<Real>& h) {
  std::size_t total = 0;
  for (const auto& l : h.levels)
    total += l.ownedA.bytes() + l.fineValues.size() * sizeof(Real) + l.p.bytes() + l.r.bytes() +
             l.invDiag.size() * sizeof(Real);
  return total + static_cast<std::size_t>(h.coarseRows) * h.coarseRows * sizeof(double);
}
}  // namespace

std::size_t AmgPreconditioner::bytes() const {
  return hierarchyBytes(impl_->single) + hierarchyBytes(impl_->twice);
}

double AmgPreconditioner::operatorComplexity() const {
  double total = 0;
  for (const auto& l : impl_->info) total += static_cast<double>(l.nonZeros);
  return total / static_cast<double>(impl_->info.front().nonZeros);
}

std::shared_ptr<AmgPreconditioner::Workspace> AmgPreconditioner::makeWorkspace(int width) const {
  auto ws = std::make_shared<Workspace>();
  ws->width = width;
  const auto& info = impl_->info;
  const std::size_t levels = info.size();
  auto sized = [&](auto& vecs, int columns) {
    vecs.resize(levels);
    for (std::size_t l = 0; l < levels; ++l)
      vecs[l].assign(static_cast<std::size_t>(info[l].rows) * columns, 0);
  };
  if (impl_->options.singlePrecision) {
    const int padded = paddedWidth(width);
    sized(ws->bf, padded), sized(ws->xf, padded), sized(ws->rf, padded), sized(ws->df, padded);
    ws->fineB.assign(static_cast<std::size_t>(info[0].rows) * padded, 0);
    ws->fineX.assign(static_cast<std::size_t>(info[0].rows) * padded, 0);
  } else {
    sized(ws->bd, width), sized(ws->xd, width), sized(ws->rd, width), sized(ws->dd, width);
  }
  ws->coarseB.resize(
      impl_->options.singlePrecision ? impl_->single.coarseRows : impl_->twice.coarseRows, width);
  return ws;
}

namespace {

/// W: the columns stored per block row (padded, see paddedWidth); the dense coarsest solve
/// takes only the coarseB.cols() real ones (the others stay zero).
template <int W, class Real>
void vcycle(const Hierarchy<Real>& h, const AmgOptions& o, std::size_t level, const Real* b,
            Real* x, std::vector<std::vector<Real>>& bs, std::vector<std::vector<Real>>& xs,
            std::vector<std::vector<Real>>& rs, std::vector<std::vector<Real>>& ds,
            Eigen::MatrixXd& coarseB) {
  if (level == h.levels.size()) {
    const int n = h.coarseRows, real = static_cast<int>(coarseB.cols());
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < real; ++c) coarseB(i, c) = b[i * W + c];
    const Eigen::MatrixXd sol = h.coarse.solve(coarseB);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < real; ++c) x[i * W + c] = static_cast<Real>(sol(i, c));
    return;
  }
  const Level<Real>& lv = h.levels[level];
  Real* r = rs[level].data();
  Real* d = ds[level].data();
  if (lv.p.rows == 0) {  // smoother-only last level
    chebyshev<W>(lv, std::max(8, 2 * o.smootherDegree), o.eigenRatio, b, x, r, d, true);
    return;
  }
  chebyshev<W>(lv, o.smootherDegree, o.eigenRatio, b, x, r, d, true);
  const std::size_t n = static_cast<std::size_t>(lv.a.rows);
  const CsrView<Real>& a = lv.a;
  parallelRanges(
      n,
      [&](std::size_t bg, std::size_t e) {
        multiplyRows<W>(a, x, r, bg, e);
        for (std::size_t i = bg * W; i < e * W; ++i) r[i] = b[i] - r[i];
      },
      512);
  Real* bc = bs[level + 1].data();
  Real* xc = xs[level + 1].data();
  multiply<W>(lv.r, r, bc);
  vcycle<W>(h, o, level + 1, bc, xc, bs, xs, rs, ds, coarseB);
  multiplyAdd<W>(lv.p, xc, x);
  chebyshev<W>(lv, o.smootherDegree, o.eigenRatio, b, x, r, d, false);
}

}  // namespace

template <int W>
void AmgPreconditioner::apply(const double* r, double* z, Workspace& ws) const {
  if (ws.width != W) throw Error("multigrid: workspace made for another column count");
  ws.coarseB.resize(ws.coarseB.rows(), W);
  const AmgOptions& o = impl_->options;
  if (o.singlePrecision) {
    constexpr int P = paddedWidth(W);
    float* b = ws.fineB.data();  // padding columns: zero since makeWorkspace
    float* x = ws.fineX.data();
    const std::size_t rows = static_cast<std::size_t>(impl_->info[0].rows);
    parallelRanges(
        rows,
        [&](std::size_t bg, std::size_t e) {
          for (std::size_t i = bg; i < e; ++i)
            for (int c = 0; c < W; ++c) b[i * P + c] = static_cast<float>(r[i * W + c]);
        },
        4096 / W);
    vcycle<P>(impl_->single, o, 0, b, x, ws.bf, ws.xf, ws.rf, ws.df, ws.coarseB);
    parallelRanges(
        rows,
        [&](std::size_t bg, std::size_t e) {
          for (std::size_t i = bg; i < e; ++i)
            for (int c = 0; c < W; ++c) z[i * W + c] = x[i * P + c];
        },
        4096 / W);
  } else {
    vcycle<W>(impl_->twice, o, 0, r, z, ws.bd, ws.xd, ws.rd, ws.dd, ws.coarseB);
  }
}

template void AmgPreconditioner::apply<1>(const double*, double*, Workspace&) const;
template void AmgPreconditioner::apply<2>(const double*, double*, Workspace&) const;
template void AmgPreconditioner::apply<3>(const double*, double*, Workspace&) const;
template void AmgPreconditioner::apply<4>(const double*, double*, Workspace&) const;
template void AmgPreconditioner::apply<5>(const double*, double*, Workspace&) const;
template void AmgPreconditioner::apply<6>(const double*, double*, Workspace&) const;

}  // namespace tfd::core::linalg
