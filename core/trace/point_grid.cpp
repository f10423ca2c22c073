#include "core/trace/point_grid.h"

#include <cmath>

#include "core/error.h"

namespace tfd::core {

PointGrid::PointGrid(double cellSize) : cellSize_(cellSize) {
  if (!(cellSize > 0) || !std::isfinite(cellSize)) throw Error("point grid: bad cell size");
}

std::int64_t PointGrid::cell(double x) const {
  return static_cast<std::int64_t>(std::floor(x / cellSize_));
}

std::uint64_t PointGrid::key(std::int64_t i, std::int64_t j, std::int64_t k) const {
  // 21 bits per axis (two's complement wrap keeps distinct cells distinct near the origin;
  // far cells may share a bucket, which only costs time: entries carry their positions).
  const auto b = [](std::int64_t v) { return std::uint64_t(v) & 0x1fffffu; };
  return b(i) | b(j) << 21 | b(k) << 42;
}

void PointGrid::insert(const Vec3& p, int line, double arc) {
  const std::uint64_t k = key(cell(p.x()), cell(p.y()), cell(p.z()));
  cells_[k].push_back({p, line, arc});
  journal_.push_back(k);
}

bool PointGrid::anyWithin(const Vec3& p, double r, int line, double arc, double window) const {
  const double r2 = r * r;
  const std::int64_t i0 = cell(p.x() - r), i1 = cell(p.x() + r);
  const std::int64_t j0 = cell(p.y() - r), j1 = cell(p.y() + r);
  const std::int64_t k0 = cell(p.z() - r), k1 = cell(p.z() + r);
  for (std::int64_t k = k0; k <= k1; ++k)
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i) {
        const auto it = cells_.find(key(i, j, k));
        if (it == cells_.end()) continue;
        for (const Entry& e : it->second) {
          if ((e.p - p).squaredNorm() >= r2) continue;
          if (e.line == line && std::abs(e.arc - arc) <= window) continue;
          return true;
        }
      }
  return false;
}

void PointGrid::rollback() {
  // Each journal entry is one point at the back of its cell (later points of the same cell
  // were journaled later), so undo in reverse order.
  for (auto it = journal_.rbegin(); it != journal_.rend(); ++it) {
    auto cell = cells_.find(*it);
    cell->second.pop_back();
    if (cell->second.empty()) cells_.erase(cell);
  }
  journal_.clear();
}

}  // namespace tfd::core
