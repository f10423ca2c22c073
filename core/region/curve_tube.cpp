#include "core/region/curve_tube.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/point_locator.h"

namespace tfd::core {
namespace {

using CellKey = std::array<std::int64_t, 3>;

/// Segments bucketed by the cells their r-inflated bounding boxes overlap: every segment within
/// r of a point is listed in the point's cell.
class SegmentGrid {
 public:
  SegmentGrid(std::span<const Vec3> points, bool closed, double radius, double cellSize)
      : points_(points), closed_(closed), cell_(cellSize) {
    const int segments = segmentCount();
    for (int s = 0; s < segments; ++s) {
      const Vec3 a = points_[s], b = points_[(s + 1) % points_.size()];
      const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / cell_)));
      for (int k = 0; k < pieces; ++k) {
        const Vec3 p = a + (b - a) * (double(k) / pieces);
        const Vec3 q = a + (b - a) * (double(k + 1) / pieces);
        const CellKey lo = keyOf(p.cwiseMin(q).array() - radius);
        const CellKey hi = keyOf(p.cwiseMax(q).array() + radius);
        for (auto i = lo[0]; i <= hi[0]; ++i)
          for (auto j = lo[1]; j <= hi[1]; ++j)
            for (auto l = lo[2]; l <= hi[2]; ++l) entries_.push_back({{i, j, l}, s});
      }
    }
    std::sort(entries_.begin(), entries_.end());
    entries_.erase(std::unique(entries_.begin(), entries_.end()), entries_.end());
  }

  int segmentCount() const {
    return static_cast<int>(closed_ ? points_.size() : points_.size() - 1);
  }

  /// Closest polyline point among the segments listed in p's cell; distance = +inf if none.
  TubeVertex closest(const Vec3& p) const {
    TubeVertex best;
    best.distance = std::numeric_limits<double>::infinity();
    const CellKey key = keyOf(p);
    auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{key, -1});
    for (; it != entries_.end() && it->key == key; ++it) {
      const Vec3& a = points_[it->segment];
      const Vec3& b = points_[(it->segment + 1) % points_.size()];
      const double t = closestSegmentParameter(p, a, b);
      const double d = (p - ((1 - t) * a + t * b)).norm();
      if (d < best.distance) best = {-1, it->segment, t, d};
    }
    return best;
  }

 private:
  struct Entry {
    CellKey key;
    int segment;
    auto operator<=>(const Entry&) const = default;
  };
  CellKey keyOf(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }

  std::span<const Vec3> points_;
  bool closed_;
  double cell_;
  std::vector<Entry> entries_;
};

}  // namespace

double closestSegmentParameter(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double ee = e.squaredNorm();
  if (ee == 0) return 0;
  return std::clamp((p - a).dot(e) / ee, 0.0, 1.0);
}

TubeQuery findTubeVertices(const TetMesh& mesh, std::span<const Vec3> polyline, bool closed,
                           double radius) {
  if (!std::isfinite(radius) || radius <= 0) {
    std::ostringstream s;
    s << "curve tube: radius must be a positive number, got " << radius;
    throw Error(s.str());
  }
  const std::size_t minimum = closed ? 3 : 2;
  if (polyline.size() < minimum) {
    throw Error(std::string("curve tube: an ") + (closed ? "closed" : "open") +
                " curve needs at least " + std::to_string(minimum) + " points, got " +
                std::to_string(polyline.size()));
  }
  double length = 0;
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    if (!polyline[i].allFinite()) {
      throw Error("curve tube: curve point " + std::to_string(i) + " is not finite");
    }
    if (i > 0) length += (polyline[i] - polyline[i - 1]).norm();
  }
  // Cells no smaller than r, and (for a radius far below the mesh resolution) no smaller than
  // a quarter edge, so a thin tube does not fill memory with cells.
  const double cell = std::max({radius, 0.25 * mesh.meanEdgeLength(), length / 2e5});
  const SegmentGrid grid(polyline, closed, radius, cell);

  TubeQuery out;
  const PointLocator& locator = mesh.locator();
  const auto& tets = mesh.tets();
  const auto& pos = mesh.positions();
  std::vector<unsigned char> visited(mesh.vertexCount(), 0);
  std::vector<TubeVertex> queue;
  const auto visit = [&](int v) {
    if (visited[v]) return;
    visited[v] = 1;
    TubeVertex c = grid.closest(pos[v]);
    if (c.distance <= radius) {
      c.vertex = v;
      queue.push_back(c);
    }
  };
  // Seeds: the vertices of every tet the curve passes through (points every quarter edge).
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    if (!locator.locate(polyline[i])) out.pointsOutside.push_back(static_cast<int>(i));
  }
  const double step = 0.25 * std::max(mesh.meanEdgeLength(), 1e-300);
  for (int s = 0; s < grid.segmentCount(); ++s) {
    const Vec3 a = polyline[s], b = polyline[(s + 1) % polyline.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int k = 0; k <= pieces; ++k) {
      if (const auto hit = locator.locate(a + (b - a) * (double(k) / pieces))) {
        for (int v : tets[hit->tet]) visit(v);
      }
    }
  }
  // Breadth-first growth through the tube (edges of the tets around each tube vertex).
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int v = queue[head].vertex;
    for (int t : mesh.vertexTets(v)) {
      for (int w : tets[t]) visit(w);
    }
  }
  std::sort(queue.begin(), queue.end(),
            [](const TubeVertex& a, const TubeVertex& b) { return a.vertex < b.vertex; });
  out.vertices = std::move(queue);
  return out;
}

}  // namespace tfd::core
