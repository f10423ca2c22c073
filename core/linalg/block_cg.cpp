#include "core/linalg/block_cg.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace tfd::core::linalg {

template <int W>
CgResult blockPcg(const CsrMatrix<double>& a, const double* b, double* x,
                  const AmgPreconditioner& preconditioner, const CgOptions& options,
                  const Progress& progress) {
  const std::size_t n = static_cast<std::size_t>(a.rows);
  CgResult result;
  std::vector<double> r(n * W), z(n * W), p(n * W), q(n * W);
  auto workspace = preconditioner.makeWorkspace(W);

  // r = b − A x; squared norms of b and r.
  auto residual = [&]() {
    return deterministicSums<2 * W>(
        n, [&](std::size_t bg, std::size_t e, std::array<double, 2 * W>& s) {
          multiplyRows<W>(a, x, r.data(), bg, e);
          for (std::size_t i = bg; i < e; ++i)
            for (int c = 0; c < W; ++c) {
              const std::size_t k = i * W + c;
              r[k] = b[k] - r[k];
              s[c] += b[k] * b[k];
              s[W + c] += r[k] * r[k];
            }
        });
  };
  const auto initial = residual();
  std::array<double, W> reference{};
  std::array<bool, W> active{};
  bool anyActive = false;
  for (int c = 0; c < W; ++c) {
    reference[c] = std::sqrt(initial[c] > 0 ? initial[c] : initial[W + c]);
    active[c] = std::sqrt(initial[W + c]) > options.tolerance * reference[c];
    anyActive = anyActive || active[c];
  }
  auto dotRZ = [&]() {
    return deterministicSums<W>(n, [&](std::size_t bg, std::size_t e, std::array<double, W>& s) {
      for (std::size_t k = bg * W; k < e * W; ++k) s[k % W] += r[k] * z[k];
    });
  };
  if (anyActive) {
    preconditioner.apply<W>(r.data(), z.data(), *workspace);
    p = z;
    std::array<double, W> rz = dotRZ();
    while (true) {
      progress.throwIfCancelled();
      if (result.iterations >= options.maxIterations) break;
      ++result.iterations;
      const auto pq =
          deterministicSums<W>(n, [&](std::size_t bg, std::size_t e, std::array<double, W>& s) {
            multiplyRows<W>(a, p.data(), q.data(), bg, e);
            for (std::size_t k = bg * W; k < e * W; ++k) s[k % W] += p[k] * q[k];
          });
      std::array<double, W> alpha{};
      for (int c = 0; c < W; ++c) {
        if (!active[c]) continue;
        if (!(pq[c] > 0) || !(rz[c] > 0)) {
          std::ostringstream out;
          out << "conjugate gradients: the system matrix or its preconditioner is not positive "
                 "definite (column "
              << c << ", iteration " << result.iterations << ": pᵀAp = " << pq[c]
              << ", rᵀz = " << rz[c] << ")";
          throw Error(out.str());
        }
        alpha[c] = rz[c] / pq[c];
      }
      const auto rr =
          deterministicSums<W>(n, [&](std::size_t bg, std::size_t e, std::array<double, W>& s) {
            for (std::size_t i = bg; i < e; ++i)
              for (int c = 0; c < W; ++c) {
                const std::size_t k = i * W + c;
                x[k] += alpha[c] * p[k];
                r[k] -= alpha[c] * q[k];
                s[c] += r[k] * r[k];
              }
          });
      anyActive = false;
      for (int c = 0; c < W; ++c) {
        if (active[c] && std::sqrt(rr[c]) <= options.tolerance * reference[c]) active[c] = false;
        anyActive = anyActive || active[c];
      }
      if (!anyActive) break;
      preconditioner.apply<W>(r.data(), z.data(), *workspace);
      const std::array<double, W> rzNew = dotRZ();
      std::array<double, W> beta{};
      for (int c = 0; c < W; ++c) beta[c] = active[c] && rz[c] > 0 ? rzNew[c] / rz[c] : 0.0;
      rz = rzNew;
      parallelRanges(
          n,
          [&](std::size_t bg, std::size_t e) {
            for (std::size_t i = bg; i < e; ++i)
              for (int c = 0; c < W; ++c) {
                const std::size_t k = i * W + c;
                p[k] = active[c] ? z[k] + beta[c] * p[k] : 0.0;
              }
          },
          2048);
    }
  }
  const auto final = residual();
  result.converged = true;
  for (int c = 0; c < W; ++c) {
    const double rel = reference[c] > 0 ? std::sqrt(final[W + c]) / reference[c] : 0.0;
    result.relativeResidual = std::max(result.relativeResidual, rel);
    // Allow for the drift between the recursive and the true residual.
    if (rel > 10 * options.tolerance) result.converged = false;
  }
  if (!result.converged) {
    std::ostringstream out;
    out << "conjugate gradients did not converge: relative residual " << result.relativeResidual
        << " after " << result.iterations << " iterations (tolerance " << options.tolerance << ")";
    throw Error(out.str());
  }
  return result;
}

template CgResult blockPcg<1>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);
template CgResult blockPcg<2>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);
template CgResult blockPcg<3>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);
template CgResult blockPcg<4>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);
template CgResult blockPcg<5>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);
template CgResult blockPcg<6>(const CsrMatrix<double>&, const double*, double*,
                              const AmgPreconditioner&, const CgOptions&, const Progress&);

}  // namespace tfd::core::linalg
