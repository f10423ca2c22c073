#include "core/edit/angle_field.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <optional>
#include <string>

#include "core/edit/reference_field.h"
#include "core/error.h"
#include "core/linalg/amg.h"
#include "core/linalg/block_cg.h"
#include "core/solve/laplacian.h"

namespace tfd::core {
namespace {

/// Free vertices reachable from none held through free vertices make K_FF singular.
void checkEveryFreePieceIsHeld(const RegionComplex& region, const std::vector<char>& held) {
  const int n = static_cast<int>(region.vertices.size());
  std::vector<char> reached(n, 0);
  std::deque<int> queue;
  for (int i = 0; i < n; ++i)
    if (held[i]) reached[i] = 1, queue.push_back(i);
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    for (int k = region.start[i]; k < region.start[i + 1]; ++k) {
      const int j = region.neighbour[k];
      if (!reached[j]) reached[j] = 1, queue.push_back(j);
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!reached[i]) {
      throw Error("angle field: free vertex " + std::to_string(region.vertices[i]) +
                  " is not connected to any held vertex of the region");
    }
  }
}

/// Cotangent weight K_ij (core/solve/laplacian.h) per local edge that touches a vertex with
/// row[i] >= 0 (a free vertex), zero elsewhere: Σ over the region's tets around the edge, in
/// ascending tet order, of tetStiffness. Every tet around a free vertex is a region tet, so
/// these are the full mesh entries (the same sums as assembleStiffnessRows, in the same order),
/// at a cost proportional to the region instead of the mesh.
std::vector<double> edgeStiffness(const TetMesh& mesh, const RegionComplex& region,
                                  const std::vector<int>& row) {
  const int count = static_cast<int>(region.tets.size());
  const auto& pos = mesh.positions();
  // In chunks: the tets' stiffness in parallel into a buffer that stays in cache, then summed
  // in ascending tet order.
  constexpr int kChunk = 1 << 15;
  std::vector<std::array<double, 6>> perTet(std::min(count, kChunk));
  std::vector<char> wanted(perTet.size(), 0);
  std::vector<double> weight(region.edges.size(), 0.0);
  for (int first = 0; first < count; first += kChunk) {
    const int last = std::min(count, first + kChunk);
    tbb::parallel_for(
        tbb::blocked_range<int>(first, last, 1024), [&](const tbb::blocked_range<int>& r) {
          for (int lt = r.begin(); lt != r.end(); ++lt) {
            const auto& v = mesh.tets()[region.tets[lt]];
            bool touches = false;
            for (int c = 0; c < 4; ++c) touches = touches || row[region.localVertex(v[c])] >= 0;
            wanted[lt - first] = touches;
            if (touches)
              perTet[lt - first] = tetStiffness(pos[v[0]], pos[v[1]], pos[v[2]], pos[v[3]]);
          }
        });
    for (int lt = first; lt < last; ++lt) {  // sequential: each sum in ascending tet order
      if (!wanted[lt - first]) continue;
      const auto& edges = mesh.tetEdges()[region.tets[lt]];
      for (int e = 0; e < 6; ++e) weight[region.localEdge(edges[e])] += perTet[lt - first][e];
    }
  }
  return weight;
}

template <int W>
linalg::CgResult runCg(const linalg::CsrMatrix<double>& a, const std::vector<double>& b,
                       std::vector<double>& x, const linalg::AmgPreconditioner& amg,
                       const linalg::CgOptions& options, const Progress& progress) {
  return linalg::blockPcg<W>(a, b.data(), x.data(), amg, options, progress);
}

}  // namespace

std::vector<double> liftAngles(const RegionComplex& region, const std::vector<char>& held,
                               const std::vector<double>& raw, const std::vector<double>& jumps,
                               double period) {
  const int n = static_cast<int>(region.vertices.size());
  std::vector<double> theta(n, 0.0);
  std::vector<char> assigned(n, 0);
  int seed = -1;
  for (int i = 0; i < n && seed < 0; ++i)
    if (held[i]) seed = i;
  if (seed < 0) return theta;
  theta[seed] = raw[seed];
  assigned[seed] = 1;
  std::deque<int> queue{seed};
  while (!queue.empty()) {
    const int a = queue.front();
    queue.pop_front();
    for (int k = region.start[a]; k < region.start[a + 1]; ++k) {
      const int b = region.neighbour[k];
      if (assigned[b]) continue;
      assigned[b] = 1;
      const double predicted = theta[a] + orientedJump(jumps[region.neighbourEdge[k]], a, b);
      if (held[b]) {
        theta[b] = raw[b] + period * std::round((predicted - raw[b]) / period);  // Eq. 5
        queue.push_front(b);
      } else {
        theta[b] = predicted;
        queue.push_back(b);
      }
    }
  }
  return theta;
}

struct JumpLaplacian::System {
  std::vector<int> freeLocal, row;  ///< free local vertices; local vertex -> matrix row or -1
  /// K_ij of each free row's held neighbours j, in the row's neighbour order, from
  /// heldStart[r] (the free neighbours' are the off-diagonal entries of `a`).
  std::vector<int> heldStart;
  std::vector<double> heldWeight;
  linalg::CsrMatrix<double> a;
  std::optional<linalg::AmgPreconditioner> amg;
};

JumpLaplacian::JumpLaplacian(const TetMesh& mesh, const RegionComplex& region,
                             const std::vector<char>& held, const Progress& progress,
                             HeldCheck check)
    : region_(region), system_(std::make_unique<System>()) {
  const int n = static_cast<int>(region.vertices.size());
  if (held.size() != static_cast<std::size_t>(n))
    throw Error("angle field: held does not match the region");
  System& s = *system_;
  s.row.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    if (held[i]) continue;
    s.row[i] = static_cast<int>(s.freeLocal.size());
    s.freeLocal.push_back(i);
  }
  if (s.freeLocal.empty()) return;
  if (check == HeldCheck::Verify) {
    checkEveryFreePieceIsHeld(region, held);
    for (int i : s.freeLocal) {
      for (int t : mesh.vertexTets(region.vertices[i]))
        if (region.localTet(t) < 0)
          throw Error("angle field: free vertex " + std::to_string(region.vertices[i]) +
                      " has a tet outside the region");
    }
  }
  const std::vector<double> weight = edgeStiffness(mesh, region, s.row);  // per local edge
  // K_FF row by row: the off-diagonals in neighbour order with the diagonal placed before the
  // first higher column; the held neighbours' weights beside it (for the right-hand sides).
  // Rows are independent: counted, then filled, in parallel.
  const int m = static_cast<int>(s.freeLocal.size());
  linalg::CsrMatrix<double>& a = s.a;
  a.rows = a.cols = m;
  a.start.assign(m + 1, 0);
  s.heldStart.assign(m + 1, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, m, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int r = b.begin(); r != b.end(); ++r) {
      const int i = s.freeLocal[r];
      int count = 1, held = 0;  // the diagonal
      for (int k = region.start[i]; k < region.start[i + 1]; ++k) {
        const bool isFree = s.row[region.neighbour[k]] >= 0;
        count += isFree, held += !isFree;
      }
      a.start[r + 1] = count;
      s.heldStart[r + 1] = held;
    }
  });
  for (int r = 0; r < m; ++r) a.start[r + 1] += a.start[r], s.heldStart[r + 1] += s.heldStart[r];
  a.index.resize(a.start[m]);
  a.value.resize(a.start[m]);
  s.heldWeight.resize(s.heldStart[m]);
  tbb::parallel_for(tbb::blocked_range<int>(0, m, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int r = b.begin(); r != b.end(); ++r) {
      const int i = s.freeLocal[r];
      int at = a.start[r], diagonal = -1, held = s.heldStart[r];
      double offDiagonal = 0;
      for (int k = region.start[i]; k < region.start[i + 1]; ++k) {
        const int j = region.neighbour[k];
        if (diagonal < 0 && j > i) diagonal = at++;
        const double kij = weight[region.neighbourEdge[k]];
        offDiagonal += kij;
        if (s.row[j] >= 0)
          a.index[at] = s.row[j], a.value[at++] = kij;
        else
          s.heldWeight[held++] = kij;
      }
      if (diagonal < 0) diagonal = at++;
      a.index[diagonal] = r;
      a.value[diagonal] = -offDiagonal;  // rows of K sum to zero
    }
  });
  progress.throwIfCancelled();
  s.amg.emplace(a);
}

JumpLaplacian::~JumpLaplacian() = default;
JumpLaplacian::JumpLaplacian(JumpLaplacian&&) noexcept = default;

JumpSolveResult JumpLaplacian::solve(const std::vector<double>& jumps, std::vector<double>& values,
                                     int width, const JumpSolveOptions& options,
                                     const Progress& progress) const {
  const RegionComplex& region = region_;
  const System& s = *system_;
  const int n = static_cast<int>(region.vertices.size());
  if (width < 1 || width > 4) throw Error("angle field: 1 to 4 columns");
  // Jumps for every column, or for the first only (the others have none).
  const int jumpColumns = jumps.size() == region.edges.size() ? 1 : width;
  if (values.size() != static_cast<std::size_t>(n) * width ||
      jumps.size() != region.edges.size() * jumpColumns) {
    throw Error("angle field: values or jumps do not match the region");
  }
  JumpSolveResult result;
  result.freeVertices = static_cast<int>(s.freeLocal.size());
  if (s.freeLocal.empty()) return result;
  const int m = static_cast<int>(s.freeLocal.size());
  std::vector<double> rhs(static_cast<std::size_t>(m) * width, 0.0), x(rhs.size());
  const linalg::CsrMatrix<double>& a = s.a;
  tbb::parallel_for(tbb::blocked_range<int>(0, m, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int r = b.begin(); r != b.end(); ++r) {
      const int i = s.freeLocal[r];
      // K_ij from the row of K_FF (skipping its diagonal, placed before the first higher
      // column) or from the held weights, in the row's neighbour order.
      int at = a.start[r], held = s.heldStart[r];
      bool diagonal = false;
      for (int k = region.start[i]; k < region.start[i + 1]; ++k) {
        const int j = region.neighbour[k], edge = region.neighbourEdge[k];
        if (!diagonal && j > i) diagonal = true, ++at;
        const bool isFree = s.row[j] >= 0;
        const double kij = isFree ? a.value[at++] : s.heldWeight[held++];
        for (int c = 0; c < jumpColumns; ++c)  // r_i = Σ_j K_ij g_ij (Eq. 6)
          rhs[r * width + c] += kij * orientedJump(jumps[edge * jumpColumns + c], i, j);
        if (!isFree) {  // − Σ_{j held} K_ij θ_j
          for (int c = 0; c < width; ++c) rhs[r * width + c] -= kij * values[j * width + c];
        }
      }
      for (int c = 0; c < width; ++c) x[r * width + c] = values[i * width + c];
    }
  });
  progress.throwIfCancelled();
  const linalg::CgOptions cg{options.tolerance, options.maxIterations};
  linalg::CgResult solved;
  switch (width) {
    case 1:
      solved = runCg<1>(s.a, rhs, x, *s.amg, cg, progress);
      break;
    case 2:
      solved = runCg<2>(s.a, rhs, x, *s.amg, cg, progress);
      break;
    case 3:
      solved = runCg<3>(s.a, rhs, x, *s.amg, cg, progress);
      break;
    default:
      solved = runCg<4>(s.a, rhs, x, *s.amg, cg, progress);
      break;
  }
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < width; ++c) values[s.freeLocal[r] * width + c] = x[r * width + c];
  result.iterations = solved.iterations;
  result.relativeResidual = solved.relativeResidual;
  return result;
}

JumpSolveResult solveJumpLaplacian(const TetMesh& mesh, const RegionComplex& region,
                                   const std::vector<char>& held, const std::vector<double>& jumps,
                                   std::vector<double>& values, int width,
                                   const JumpSolveOptions& options, const Progress& progress) {
  // The sizes first, before the set-up's own checks (as the one-step solve always did).
  if (width < 1 || width > 4) throw Error("angle field: 1 to 4 columns");
  if (held.size() != region.vertices.size() || values.size() != region.vertices.size() * width ||
      (jumps.size() != region.edges.size() * width && jumps.size() != region.edges.size())) {
    throw Error("angle field: held, values or jumps do not match the region");
  }
  return JumpLaplacian(mesh, region, held, progress).solve(jumps, values, width, options, progress);
}

}  // namespace tfd::core
