#pragma once
// Matrices for the linear-algebra tests: the 7-point finite-difference Poisson matrix of an
// n × n × n grid with Dirichlet boundary (symmetric positive definite, known spectrum), dense
// copies and a deterministic pseudo-random sparse matrix.
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "core/linalg/csr_matrix.h"

namespace tfd::core::linalg::testing {

inline int gridIndex(int n, int i, int j, int k) { return i + n * (j + n * k); }

/// −Δ on the interior points of a grid of n³ unknowns (diagonal 6, neighbours −1).
inline CsrMatrix<double> poisson3d(int n) {
  CsrMatrix<double> a;
  a.rows = a.cols = n * n * n;
  a.start.assign(1, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto add = [&](int ii, int jj, int kk, double v) {
          if (ii < 0 || jj < 0 || kk < 0 || ii >= n || jj >= n || kk >= n) return;
          a.index.push_back(gridIndex(n, ii, jj, kk));
          a.value.push_back(v);
        };
        add(i, j, k - 1, -1), add(i, j - 1, k, -1), add(i - 1, j, k, -1), add(i, j, k, 6);
        add(i + 1, j, k, -1), add(i, j + 1, k, -1), add(i, j, k + 1, -1);
        a.start.push_back(static_cast<int>(a.index.size()));
      }
  return a;
}

inline Eigen::MatrixXd dense(const CsrMatrix<double>& a) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(a.rows, a.cols);
  for (int i = 0; i < a.rows; ++i)
    for (int m = a.start[i]; m < a.start[i + 1]; ++m) d(i, a.index[m]) += a.value[m];
  return d;
}

/// Deterministic value in [−1, 1] for an integer key (splitmix64).
inline double hashUnit(std::uint64_t i) {
  std::uint64_t z = i * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/// A rows × cols matrix with about `perRow` entries per row at pseudo-random columns
/// (ascending, no repeats), values in [−1, 1].
inline CsrMatrix<double> randomSparse(int rows, int cols, int perRow, std::uint64_t seed) {
  CsrMatrix<double> a;
  a.rows = rows, a.cols = cols;
  a.start.assign(1, 0);
  std::uint64_t key = seed * 1000003;
  for (int i = 0; i < rows; ++i) {
    for (int c = 0; c < cols; ++c) {
      if (hashUnit(key++) < 2.0 * perRow / cols - 1) {
        a.index.push_back(c);
        a.value.push_back(hashUnit(key++));
      }
    }
    a.start.push_back(static_cast<int>(a.index.size()));
  }
  return a;
}

}  // namespace tfd::core::linalg::testing
