#include "core/surface/surface_weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>

namespace tfd::core {
namespace {

using Key = std::array<std::uint64_t, 3>;

Key keyOf(const Vec3& p) {
  Key key;
  for (int i = 0; i < 3; ++i) {
    const double v = p[i] + 0.0;  // -0.0 becomes +0.0, so both weld
    std::memcpy(&key[i], &v, sizeof v);
  }
  return key;
}

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the three bit patterns
    for (std::uint64_t v : k) h = (h ^ v ^ (v >> 29)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

/// Replaces every vertex v by kept[newId[v]] and drops the triangles that lose a corner.
WeldReport applyWeld(SurfaceMesh& mesh, std::vector<Vec3> kept, const std::vector<int>& newId) {
  WeldReport report;
  report.mergedVertices = mesh.positions.size() - kept.size();
  if (report.mergedVertices == 0) return report;
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const std::array<int, 3> w{newId[t[0]], newId[t[1]], newId[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
      ++report.droppedTriangles;
      continue;
    }
    triangles.push_back(w);
  }
  mesh.positions = std::move(kept);
  mesh.triangles = std::move(triangles);
  return report;
}

using Cell = std::array<std::int64_t, 3>;

/// The grid cell of p for cells of side `cell`, clamped far inside the int64 range.
Cell cellOf(const Vec3& p, double cell) {
  Cell c;
  for (int i = 0; i < 3; ++i) c[i] = std::int64_t(std::clamp(std::floor(p[i] / cell), -4e18, 4e18));
  return c;
}

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ std::uint64_t(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

/// Items 0, 1, 2, ... filed once each by grid cell: an open-addressing table from a cell to the
/// item filed last in it, and from each item to the one filed before it in its cell (one
/// allocation, where a map of lists makes one per cell).
class CellTable {
 public:
  explicit CellTable(std::size_t items) : before_(items, -1) {
    std::size_t size = 16;
    while (size < 2 * items) size *= 2;
    slots_.assign(size, Slot{});
  }
  void file(const Cell& c, int item) {
    Slot& s = slots_[find(c)];
    s.cell = c;
    before_[item] = s.last;
    s.last = item;
  }
  template <class Visit>
  void forEach(const Cell& c, Visit&& visit) const {
    for (int i = slots_[find(c)].last; i >= 0; i = before_[i]) visit(i);
  }

 private:
  struct Slot {
    Cell cell{};
    int last = -1;  ///< −1: empty
  };
  /// The slot of cell c, or the empty one where it would go.
  std::size_t find(const Cell& c) const {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = CellHash{}(c)&mask;; i = (i + 1) & mask)
      if (slots_[i].last < 0 || slots_[i].cell == c) return i;
  }
  std::vector<Slot> slots_;
  std::vector<int> before_;
};

}  // namespace

WeldReport weldCoincidentVertices(SurfaceMesh& mesh) {
  std::unordered_map<Key, int, KeyHash> firstAt;
  firstAt.reserve(mesh.positions.size());
  std::vector<int> newId(mesh.positions.size());
  std::vector<Vec3> kept;
  kept.reserve(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto [it, inserted] = firstAt.emplace(keyOf(mesh.positions[v]), int(kept.size()));
    if (inserted) kept.push_back(mesh.positions[v]);
    newId[v] = it->second;
  }
  return applyWeld(mesh, std::move(kept), newId);
}

WeldReport weldCloseVertices(SurfaceMesh& mesh, double tolerance) {
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return weldCoincidentVertices(mesh);
  // Kept vertices filed by grid cell of side 2·tolerance: the points within `tolerance` of p
  // lie in the 2 × 2 × 2 cells that the cube [p − tolerance, p + tolerance]³ overlaps.
  const double side = 2 * tolerance;
  CellTable cells(mesh.positions.size());
  std::vector<int> newId(mesh.positions.size());
  std::vector<Vec3> kept;
  kept.reserve(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const Cell low = cellOf(p - Vec3::Constant(tolerance), side);
    int into = std::numeric_limits<int>::max();
    for (int corner = 0; corner < 8; ++corner) {
      const Cell c{low[0] + (corner & 1), low[1] + (corner >> 1 & 1), low[2] + (corner >> 2)};
      cells.forEach(c, [&](int k) {
        if (k < into && (kept[k] - p).norm() <= tolerance) into = k;
      });
    }
    if (into == std::numeric_limits<int>::max()) {
      into = int(kept.size());
      kept.push_back(p);
      cells.file(cellOf(p, side), into);
    }
    newId[v] = into;
  }
  return applyWeld(mesh, std::move(kept), newId);
}

std::size_t removeRepeatedTriangles(SurfaceMesh& mesh) {
  // Triangles by their sorted corners; within a group, by position in the file.
  const std::size_t n = mesh.triangles.size();
  std::vector<std::pair<std::array<int, 3>, int>> keyed(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<int, 3> k = mesh.triangles[i];
    std::sort(k.begin(), k.end());
    keyed[i] = {k, int(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  // A triangle's facing: whether its corners are an even permutation of the sorted ones.
  auto facing = [&](int i) {
    const auto& t = mesh.triangles[i];
    const int smallest = int(std::min_element(t.begin(), t.end()) - t.begin());
    return t[(smallest + 1) % 3] < t[(smallest + 2) % 3];
  };
  std::vector<char> removed(n, 0);
  std::size_t count = 0;
  for (std::size_t i = 0, j; i < n; i = j) {
    for (j = i + 1; j < n && keyed[j].first == keyed[i].first; ++j) {
    }
    if (j - i == 1) continue;
    std::vector<int> up, down;  // in file order
    for (std::size_t k = i; k < j; ++k)
      (facing(keyed[k].second) ? up : down).push_back(keyed[k].second);
    // Opposite pairs cancel (the last copies of each side first); one of the rest stays.
    const std::size_t pairs = std::min(up.size(), down.size());
    auto& rest = up.size() > down.size() ? up : down;
    for (std::size_t k = 0; k < pairs; ++k)
      removed[up[up.size() - 1 - k]] = removed[down[down.size() - 1 - k]] = 1;
    for (std::size_t k = 1; k + pairs < rest.size(); ++k) removed[rest[k]] = 1;
  }
  std::vector<std::array<int, 3>> kept;
  kept.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (removed[i])
      ++count;
    else
      kept.push_back(mesh.triangles[i]);
  }
  mesh.triangles = std::move(kept);
  return count;
}

double openEdgeWeldDistance(const SurfaceMesh& mesh, double within) {
  std::vector<std::uint64_t> sides;  // (lo, hi) of every triangle side
  sides.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = std::minmax(t[k], t[(k + 1) % 3]);
      sides.push_back(std::uint64_t(std::uint32_t(lo)) << 32 | std::uint32_t(hi));
    }
  std::sort(sides.begin(), sides.end());
  std::vector<std::array<int, 2>> open;
  for (std::size_t i = 0, j; i < sides.size(); i = j) {
    for (j = i + 1; j < sides.size() && sides[j] == sides[i]; ++j) {
    }
    if (j - i == 1) open.push_back({int(sides[i] >> 32), int(sides[i] & 0xffffffffu)});
  }
  if (open.empty()) return 0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!(within > 0) || !std::isfinite(within)) return kInf;
  // Both ends of every open edge, filed by grid cell (side `within`): end 2e + k of edge e.
  CellTable ends(2 * open.size());
  for (int e = 0; e < int(open.size()); ++e)
    for (int k = 0; k < 2; ++k) ends.file(cellOf(mesh.positions[open[e][k]], within), 2 * e + k);
  auto gap = [&](int a, int b) { return (mesh.positions[a] - mesh.positions[b]).norm(); };
  // Each open edge's nearest twin: another open edge whose ends lie within `within` of its
  // own, matched end to end (a shared end is 0 away); the edge's gap is the farther end.
  double widest = 0;
  for (int e = 0; e < int(open.size()); ++e) {
    const int a = open[e][0], b = open[e][1];  // plain ints: a lambda below reads them
    const auto c = cellOf(mesh.positions[a], within);
    double nearest = kInf;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          ends.forEach({c[0] + dx, c[1] + dy, c[2] + dz}, [&](int end) {
            const int f = end / 2;
            if (f == e) return;
            const auto [p, q] = open[f];
            nearest =
                std::min({nearest, std::max(gap(a, p), gap(b, q)), std::max(gap(a, q), gap(b, p))});
          });
        }
    if (!(nearest <= within)) return kInf;
    widest = std::max(widest, nearest);
  }
  return widest;
}

}  // namespace tfd::core
