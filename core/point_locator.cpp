#include "core/point_locator.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "core/tet_mesh.h"

namespace tfd::core {

LocatorGrid::LocatorGrid(const TetMesh& mesh) {
  const Vec3 extent = (mesh.boundsMax() - mesh.boundsMin()).cwiseMax(1e-12);
  // About one tet per cell: cell volume ≈ bounding volume / tet count.
  const double cells = std::max<double>(1, static_cast<double>(mesh.tetCount()));
  cellSize = std::cbrt(extent.prod() / cells);
  cellSize = std::max(cellSize, extent.maxCoeff() / 1024);  // cap the grid at 1024 per axis
  origin = mesh.boundsMin();
  for (int a = 0; a < 3; ++a)
    dims[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cellSize)));
}

std::array<int, 3> LocatorGrid::cellOf(const Vec3& p) const {
  std::array<int, 3> c;
  for (int a = 0; a < 3; ++a)
    c[a] = std::clamp(static_cast<int>(std::floor((p[a] - origin[a]) / cellSize)), 0, dims[a] - 1);
  return c;
}

bool LocatorGrid::mayHold(const TetMesh& mesh, const Vec3& p, double tolerance) const {
  for (int a = 0; a < 3; ++a) {
    const double margin = tolerance * cellSize * dims[a];
    if (p[a] < mesh.boundsMin()[a] - margin || p[a] > mesh.boundsMax()[a] + margin) return false;
  }
  return true;
}

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(mesh), grid_(mesh) {
  const Vec3& origin = grid_.origin;
  const double cellSize = grid_.cellSize;
  const std::array<int, 3>& dims = grid_.dims;
  const auto& pos = mesh.positions();
  const auto& tets = mesh.tets();
  const std::size_t cellCount = std::size_t(dims[0]) * dims[1] * dims[2];
  cellStart_.assign(cellCount + 1, 0);
  // Each tet's cell range, computed in parallel; the two passes below only walk them.
  std::vector<std::array<int, 6>> ranges(tets.size());
  tbb::parallel_for(std::size_t(0), tets.size(), [&](std::size_t t) {
    Vec3 mn = pos[tets[t][0]], mx = mn;
    for (int i = 1; i < 4; ++i) {
      mn = mn.cwiseMin(pos[tets[t][i]]);
      mx = mx.cwiseMax(pos[tets[t][i]]);
    }
    const auto lo = grid_.cellOf(mn), hi = grid_.cellOf(mx);
    ranges[t] = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
  });
  const auto forCells = [&](auto&& visit) {
    for (int t = 0; t < static_cast<int>(tets.size()); ++t) {
      const auto& r = ranges[t];
      for (int k = r[2]; k <= r[5]; ++k)
        for (int j = r[1]; j <= r[4]; ++j)
          for (int i = r[0]; i <= r[3]; ++i) visit(t, (std::size_t(k) * dims[1] + j) * dims[0] + i);
    }
  };
  forCells([&](int, std::size_t c) { ++cellStart_[c + 1]; });
  for (std::size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
  cellTets_.resize(cellStart_.back());
  std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
  forCells([&](int t, std::size_t c) { cellTets_[fill[c]++] = t; });
  // Nearest centroid first (ties: lower tet id, so the order is deterministic): with the early
  // exit in locate(), a query usually stops at the first or second candidate.
  std::vector<Vec3> centroids(tets.size());
  tbb::parallel_for(std::size_t(0), tets.size(), [&](std::size_t t) {
    const auto& v = tets[t];
    centroids[t] = 0.25 * (pos[v[0]] + pos[v[1]] + pos[v[2]] + pos[v[3]]);
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cellCount, 4096), [&](const auto& range) {
    // Key: the float distance's bits (order-preserving for non-negative floats), then the id.
    std::vector<std::uint64_t> keyed;
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      const std::size_t i = c % dims[0], j = c / dims[0] % dims[1],
                        k = c / (std::size_t(dims[0]) * dims[1]);
      const Vec3 centre = origin + cellSize * Vec3(i + 0.5, j + 0.5, k + 0.5);
      keyed.clear();
      for (int n = cellStart_[c]; n < cellStart_[c + 1]; ++n)
        keyed.push_back(std::uint64_t(std::bit_cast<std::uint32_t>(
                            static_cast<float>((centroids[cellTets_[n]] - centre).squaredNorm())))
                            << 32 |
                        std::uint32_t(cellTets_[n]));
      std::sort(keyed.begin(), keyed.end());
      for (std::size_t n = 0; n < keyed.size(); ++n)
        cellTets_[cellStart_[c] + n] = static_cast<int>(keyed[n] & 0xffffffffu);
    }
  });
}

namespace {
/// Smallest barycentric coordinate above which a point is inside a tet beyond rounding doubt.
constexpr double kStrictlyInside = 1e-9;
}  // namespace

std::optional<TetLocation> PointLocator::locate(const Vec3& p, double tolerance) const {
  if (!grid_.mayHold(mesh_, p, tolerance)) return {};
  const auto c = grid_.cellOf(p);
  const auto& dims = grid_.dims;
  const std::size_t cell = (std::size_t(c[2]) * dims[1] + c[1]) * dims[0] + c[0];
  std::optional<TetLocation> best;
  double bestMin = -tolerance;
  for (int k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
    const int t = cellTets_[k];
    const Eigen::Vector4d b = mesh_.barycentric(t, p);
    const double m = b.minCoeff();
    if (m >= bestMin && (!best || m > bestMin || t < best->tet)) {
      bestMin = m;
      best = TetLocation{t, b};
      // Strictly inside: tets do not overlap, so no other candidate can do better.
      if (m > kStrictlyInside) break;
    }
  }
  return best;
}

std::vector<std::optional<TetLocation>> PointLocator::locateAll(
    const std::vector<Vec3>& points) const {
  std::vector<std::optional<TetLocation>> out(points.size());
  tbb::parallel_for(std::size_t(0), points.size(),
                    [&](std::size_t i) { out[i] = locate(points[i]); });
  return out;
}

namespace {

/// PointLocator::locate's preference: larger smallest coordinate, then lower tet id.
bool better(double m, int t, double bestMin, int bestTet) {
  return bestTet < 0 || m > bestMin || (m == bestMin && t < bestTet);
}

}  // namespace

std::vector<std::optional<TetLocation>> locateByScan(const TetMesh& mesh,
                                                     std::span<const Vec3> points,
                                                     double tolerance) {
  const LocatorGrid grid(mesh);
  const std::size_t np = points.size();
  std::vector<std::optional<TetLocation>> out(np);
  // Points that may be inside, with their cells.
  std::vector<std::size_t> live;
  std::vector<std::array<int, 3>> cells;
  for (std::size_t i = 0; i < np; ++i) {
    if (!grid.mayHold(mesh, points[i], tolerance)) continue;
    live.push_back(i);
    cells.push_back(grid.cellOf(points[i]));
  }
  if (live.empty()) return out;
  const auto& pos = mesh.positions();
  const auto& tets = mesh.tets();
  // Fixed chunks, each keeping its best tet per point, merged in chunk order by the same
  // total order (smallest coordinate, then id): the result does not depend on the threads.
  constexpr std::size_t kScanChunk = 1 << 16;
  const std::size_t chunks = (tets.size() + kScanChunk - 1) / kScanChunk;
  struct Best {
    int tet = -1;
    double min = 0;
  };
  std::vector<Best> best(chunks * live.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const auto& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      Best* mine = &best[c * live.size()];
      const std::size_t end = std::min(tets.size(), (c + 1) * kScanChunk);
      for (std::size_t t = c * kScanChunk; t < end; ++t) {
        Vec3 mn = pos[tets[t][0]], mx = mn;
        for (int i = 1; i < 4; ++i) {
          mn = mn.cwiseMin(pos[tets[t][i]]);
          mx = mx.cwiseMax(pos[tets[t][i]]);
        }
        const auto lo = grid.cellOf(mn), hi = grid.cellOf(mx);
        for (std::size_t k = 0; k < live.size(); ++k) {
          const auto& q = cells[k];
          if (q[0] < lo[0] || q[0] > hi[0] || q[1] < lo[1] || q[1] > hi[1] || q[2] < lo[2] ||
              q[2] > hi[2])
            continue;
          const double m = mesh.barycentric(static_cast<int>(t), points[live[k]]).minCoeff();
          if (m >= -tolerance && better(m, static_cast<int>(t), mine[k].min, mine[k].tet))
            mine[k] = {static_cast<int>(t), m};
        }
      }
    }
  });
  for (std::size_t k = 0; k < live.size(); ++k) {
    Best b;
    for (std::size_t c = 0; c < chunks; ++c) {
      const Best& x = best[c * live.size() + k];
      if (x.tet >= 0 && better(x.min, x.tet, b.min, b.tet)) b = x;
    }
    if (b.tet >= 0) out[live[k]] = TetLocation{b.tet, mesh.barycentric(b.tet, points[live[k]])};
  }
  return out;
}

std::vector<std::optional<TetLocation>> locatePoints(const TetMesh& mesh,
                                                     std::span<const Vec3> points) {
  if (mesh.hasLocator() || points.size() > kScanPointLimit) {
    const PointLocator& locator = mesh.locator();
    std::vector<std::optional<TetLocation>> out(points.size());
    tbb::parallel_for(std::size_t(0), points.size(),
                      [&](std::size_t i) { out[i] = locator.locate(points[i]); });
    return out;
  }
  return locateByScan(mesh, points);
}

}  // namespace tfd::core
