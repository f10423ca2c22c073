#include "core/solve/laplacian.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <string>

#include "core/error.h"

namespace tfd::core {

namespace {

/// Scaled barycentric gradients of a tet: ∇φ_i = c_i / det with det = 6V; scale = 1/(6 det).
struct TetGradients {
  std::array<Vec3, 4> c;
  double det = 0;
  double scale = 0;
};

inline TetGradients tetGradients(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, e3 = p3 - p0;
  TetGradients g;
  g.c[1] = e2.cross(e3);
  g.c[2] = e3.cross(e1);
  g.c[3] = e1.cross(e2);
  g.c[0] = -(g.c[1] + g.c[2] + g.c[3]);
  g.det = e1.dot(g.c[1]);
  g.scale = 1.0 / (6.0 * g.det);
  return g;
}

/// K_ij = V ∇φ_i·∇φ_j = (c_i·c_j) / (6 det). Symmetric in (i, j) bitwise.
inline double entry(const TetGradients& g, int i, int j) { return g.c[i].dot(g.c[j]) * g.scale; }

}  // namespace

std::array<double, 6> tetStiffness(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const TetGradients g = tetGradients(p0, p1, p2, p3);
  return {entry(g, 0, 1), entry(g, 0, 2), entry(g, 0, 3),
          entry(g, 1, 2), entry(g, 1, 3), entry(g, 2, 3)};
}

StiffnessRows assembleStiffness(const TetMesh& mesh) {
  // Every row: per-tet entries in parallel (one output per tet), then one sequential pass in
  // tet order adds them onto the mesh edges (each edge entry sums its tets in ascending order,
  // exactly as the row-by-row path below does, so both give bitwise equal values), then the
  // rows are laid out from the lexicographically sorted edge list: row v lists its lower
  // neighbours, itself, then its upper neighbours, already ascending.
  const auto& tets = mesh.tets();
  const auto& pos = mesh.positions();
  const auto& edges = mesh.edges();
  const auto& tetEdges = mesh.tetEdges();
  const int n = static_cast<int>(mesh.vertexCount());
  std::vector<double> edgeValue(edges.size(), 0.0);
  {
    constexpr std::size_t kBlock = 1 << 16;
    std::vector<std::array<double, 6>> block(std::min(kBlock, tets.size()));
    for (std::size_t first = 0; first < tets.size(); first += kBlock) {
      const std::size_t last = std::min(tets.size(), first + kBlock);
      linalg::parallelRanges(last - first, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
          const auto& tet = tets[first + i];
          const TetGradients g = tetGradients(pos[tet[0]], pos[tet[1]], pos[tet[2]], pos[tet[3]]);
          block[i] = {entry(g, 0, 1), entry(g, 0, 2), entry(g, 0, 3),
                      entry(g, 1, 2), entry(g, 1, 3), entry(g, 2, 3)};
        }
      });
      for (std::size_t t = first; t < last; ++t)
        for (int p = 0; p < 6; ++p) edgeValue[tetEdges[t][p]] += block[t - first][p];
    }
  }
  StiffnessRows result;
  result.vertices.resize(n);
  for (int v = 0; v < n; ++v) result.vertices[v] = v;
  linalg::CsrMatrix<double>& k = result.matrix;
  k.rows = k.cols = n;
  k.start.assign(n + 1, 0);
  for (const auto& e : edges) ++k.start[e[0] + 1], ++k.start[e[1] + 1];
  for (int v = 0; v < n; ++v) k.start[v + 1] += k.start[v] + 1;  // + 1 for the diagonal
  k.index.resize(k.start[n]);
  k.value.resize(k.start[n]);
  std::vector<int> next(k.start.begin(), k.start.end() - 1);
  std::vector<unsigned char> diagonalPlaced(n, 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int a = edges[e][0], b = edges[e][1];
    // Edges (·, b) with a smaller first vertex all come before (b, ·): place b's diagonal
    // just before its first upper neighbour.
    if (!diagonalPlaced[a]) {
      k.index[next[a]++] = a;
      diagonalPlaced[a] = 1;
    }
    k.index[next[a]] = b;
    k.value[next[a]++] = edgeValue[e];
    k.index[next[b]] = a;
    k.value[next[b]++] = edgeValue[e];
  }
  for (int v = 0; v < n; ++v)
    if (!diagonalPlaced[v]) k.index[next[v]++] = v;  // vertices without upper neighbours
  linalg::parallelRanges(n, [&](std::size_t b, std::size_t e) {
    for (std::size_t v = b; v < e; ++v) {
      double offDiagonal = 0;
      int diagonal = -1;
      for (int m = k.start[v]; m < k.start[v + 1]; ++m) {
        if (k.index[m] == static_cast<int>(v))
          diagonal = m;
        else
          offDiagonal += k.value[m];
      }
      k.value[diagonal] = -offDiagonal;
    }
  });
  return result;
}

StiffnessRows assembleStiffnessRows(const TetMesh& mesh, std::vector<int> vertices) {
  const int n = static_cast<int>(mesh.vertexCount());
  for (std::size_t r = 0; r < vertices.size(); ++r) {
    if (vertices[r] < 0 || vertices[r] >= n)
      throw Error("stiffness rows: vertex " + std::to_string(vertices[r]) +
                  " out of range (mesh has " + std::to_string(n) + " vertices)");
    if (r > 0 && vertices[r] <= vertices[r - 1])
      throw Error("stiffness rows: vertex ids must be ascending and unique");
  }
  if (vertices.size() == static_cast<std::size_t>(n)) return assembleStiffness(mesh);
  const auto& tets = mesh.tets();
  const auto& pos = mesh.positions();
  const int rows = static_cast<int>(vertices.size());
  // When many rows are wanted, compute the six entries of each tet around them once (in
  // parallel, one output per tet; only those tets, so a region's rows cost in proportion to
  // the region); for a few rows compute them on the fly. Both paths evaluate the same
  // expression, so the values are bitwise identical.
  std::unique_ptr<std::array<double, 6>[]> perTet;  // filled for the tets around the rows
  if (static_cast<std::size_t>(rows) * 4 >= static_cast<std::size_t>(n)) {
    std::vector<unsigned char> around(tets.size(), 0);
    linalg::parallelRanges(vertices.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t r = b; r < e; ++r)
        for (int t : mesh.vertexTets(vertices[r]))
          std::atomic_ref<unsigned char>(around[t]).store(1, std::memory_order_relaxed);
    });
    perTet.reset(new std::array<double, 6>[tets.size()]);  // pages touched only where filled
    linalg::parallelRanges(tets.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t t = b; t < e; ++t) {
        if (!around[t]) continue;
        const auto& tet = tets[t];
        const TetGradients g = tetGradients(pos[tet[0]], pos[tet[1]], pos[tet[2]], pos[tet[3]]);
        perTet[t] = {entry(g, 0, 1), entry(g, 0, 2), entry(g, 0, 3),
                     entry(g, 1, 2), entry(g, 1, 3), entry(g, 2, 3)};
      }
    });
  }
  // Local vertex pair (i, j) -> index into the six entries (01, 02, 03, 12, 13, 23).
  static constexpr int kPair[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
  const int chunkCount = (rows + linalg::kRowsPerChunk - 1) / linalg::kRowsPerChunk;
  std::vector<linalg::RowChunk> chunks(chunkCount);

  // Each thread's slot of every mesh vertex in the row being built (−1: not in it), reset after
  // each row: a neighbour's place is one lookup instead of a search of the row.
  tbb::enumerable_thread_specific<std::vector<int>> slots([n] { return std::vector<int>(n, -1); });
  tbb::parallel_for(
      tbb::blocked_range<int>(0, chunkCount, 1), [&](const tbb::blocked_range<int>& range) {
        std::vector<int>& slot = slots.local();
        std::vector<int> neighbours;
        std::vector<double> values;
        for (int c = range.begin(); c != range.end(); ++c) {
          linalg::RowChunk& chunk = chunks[c];
          const int begin = c * linalg::kRowsPerChunk;
          const int end = std::min(rows, begin + linalg::kRowsPerChunk);
          chunk.rowLength.reserve(end - begin);
          chunk.index.reserve(static_cast<std::size_t>(end - begin) * 16);
          chunk.value.reserve(static_cast<std::size_t>(end - begin) * 16);
          for (int r = begin; r < end; ++r) {
            const int v = vertices[r];
            const auto incident = mesh.vertexTets(v);
            // The vertex and its neighbours (the corners of its tets), ascending.
            slot[v] = 0;
            neighbours.assign(1, v);
            for (int t : incident)
              for (int u : tets[t])
                if (slot[u] < 0) slot[u] = 0, neighbours.push_back(u);
            std::sort(neighbours.begin(), neighbours.end());
            for (std::size_t k = 0; k < neighbours.size(); ++k) slot[neighbours[k]] = int(k);
            values.assign(neighbours.size(), 0.0);
            // Tets in ascending order: every entry sums the same terms in the same order as its
            // transposed entry in the row of the other vertex.
            for (int t : incident) {
              const auto& tet = tets[t];
              int local = 0;
              while (tet[local] != v) ++local;
              std::array<double, 6> k;
              if (perTet) {
                k = perTet[t];
              } else {
                const TetGradients g =
                    tetGradients(pos[tet[0]], pos[tet[1]], pos[tet[2]], pos[tet[3]]);
                for (int j = 0; j < 4; ++j)
                  if (j != local) k[kPair[local][j]] = entry(g, local, j);
              }
              for (int j = 0; j < 4; ++j)
                if (j != local) values[slot[tet[j]]] += k[kPair[local][j]];
            }
            double offDiagonal = 0;
            for (std::size_t k = 0; k < neighbours.size(); ++k)
              if (neighbours[k] != v) offDiagonal += values[k];
            values[slot[v]] = -offDiagonal;
            for (int u : neighbours) slot[u] = -1;
            chunk.index.insert(chunk.index.end(), neighbours.begin(), neighbours.end());
            chunk.value.insert(chunk.value.end(), values.begin(), values.end());
            chunk.rowLength.push_back(static_cast<int>(neighbours.size()));
          }
        }
      });
  StiffnessRows result;
  result.matrix = linalg::assembleChunks(rows, n, chunks);
  result.vertices = std::move(vertices);
  return result;
}

std::vector<double> applyStiffness(const StiffnessRows& rows, std::span<const double> u) {
  if (u.size() != static_cast<std::size_t>(rows.matrix.cols))
    throw Error("applyStiffness: expected " + std::to_string(rows.matrix.cols) + " values, got " +
                std::to_string(u.size()));
  std::vector<double> out(rows.vertices.size());
  linalg::multiply<1>(rows.matrix, u.data(), out.data());
  return out;
}

double gradientEnergy(const TetMesh& mesh, std::span<const double> u) {
  if (u.size() != mesh.vertexCount())
    throw Error("gradientEnergy: expected one value per vertex (" +
                std::to_string(mesh.vertexCount()) + "), got " + std::to_string(u.size()));
  const auto& tets = mesh.tets();
  const auto& pos = mesh.positions();
  const auto sums = linalg::deterministicSums<1>(
      tets.size(), [&](std::size_t b, std::size_t e, std::array<double, 1>& s) {
        for (std::size_t t = b; t < e; ++t) {
          const auto& tet = tets[t];
          const TetGradients g = tetGradients(pos[tet[0]], pos[tet[1]], pos[tet[2]], pos[tet[3]]);
          Vec3 grad = Vec3::Zero();
          for (int i = 0; i < 4; ++i) grad += u[tet[i]] * g.c[i];
          grad /= g.det;
          s[0] += g.det / 6.0 * grad.squaredNorm();
        }
      });
  return sums[0];
}

}  // namespace tfd::core
