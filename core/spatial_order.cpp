#include "core/spatial_order.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.h"

namespace tfd::core {

// J. Skilling, "Programming the Hilbert curve" (AIP Conf. Proc. 707, 2004): the cell's
// coordinates are turned in place into the "transposed" Hilbert index (undoing the curve's
// rotations and reflections level by level from the top, then a Gray code), whose bits, read
// one from each axis per level from the top, are the index.
std::uint64_t hilbertIndex(std::array<std::uint32_t, 3> x, int bits) {
  if (bits < 1 || bits > 21) throw Error("hilbertIndex: bits must be 1 to 21");
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t below = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (x[i] & q) {
        x[0] ^= below;  // reflect the lower bits of the first axis
      } else {
        const std::uint32_t swap = (x[0] ^ x[i]) & below;  // exchange them with axis i
        x[0] ^= swap;
        x[i] ^= swap;
      }
    }
  }
  x[1] ^= x[0];
  x[2] ^= x[1];
  std::uint32_t flip = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) flip ^= q - 1;
  for (auto& c : x) c ^= flip;
  std::uint64_t index = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) index = index << 1 | ((x[i] >> b) & 1u);
  return index;
}

std::vector<int> hilbertOrder(std::span<const Vec3> points) {
  constexpr int kBits = 21;
  if (points.empty()) return {};
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& p : points)
    if (p.allFinite()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!(lo.x() <= hi.x())) lo = hi = Vec3::Zero();
  const double side = (hi - lo).maxCoeff();
  const double scale = side > 0 ? double((1u << kBits) - 1) / side : 0.0;
  const auto n = static_cast<int>(points.size());
  std::vector<std::pair<std::uint64_t, int>> keyed(points.size());
  tbb::parallel_for(0, n, [&](int i) {
    std::array<std::uint32_t, 3> cell;
    for (int a = 0; a < 3; ++a) {
      const double c = (points[i][a] - lo[a]) * scale;  // NaN: cell 0
      cell[a] = c > 0 ? static_cast<std::uint32_t>(std::min(c, double((1u << kBits) - 1))) : 0;
    }
    keyed[i] = {hilbertIndex(cell, kBits), i};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());  // keys unique with the index: deterministic
  std::vector<int> order(points.size());
  for (int k = 0; k < n; ++k) order[k] = keyed[k].second;
  return order;
}

void renumberSpatially(std::vector<Vec3>& positions, std::vector<std::array<int, 4>>& tets,
                       std::size_t firstFree) {
  firstFree = std::min(firstFree, positions.size());
  const std::span<const Vec3> free(positions.data() + firstFree, positions.size() - firstFree);
  const std::vector<int> vertexOrder = hilbertOrder(free);
  std::vector<int> newId(positions.size());
  std::vector<Vec3> moved(positions.begin(), positions.begin() + firstFree);
  moved.resize(positions.size());
  for (std::size_t v = 0; v < firstFree; ++v) newId[v] = static_cast<int>(v);
  for (std::size_t k = 0; k < vertexOrder.size(); ++k) {
    const std::size_t old = firstFree + vertexOrder[k];
    newId[old] = static_cast<int>(firstFree + k);
    moved[firstFree + k] = positions[old];
  }
  positions = std::move(moved);

  for (const auto& tet : tets)
    for (int v : tet)
      if (v < 0 || std::size_t(v) >= positions.size())
        throw Error("renumberSpatially: a tet names vertex " + std::to_string(v) + " of " +
                    std::to_string(positions.size()));
  std::vector<Vec3> centroids(tets.size());
  tbb::parallel_for(std::size_t(0), tets.size(), [&](std::size_t t) {
    Vec3 c = Vec3::Zero();
    for (int& v : tets[t]) {
      v = newId[v];
      c += positions[v];
    }
    centroids[t] = 0.25 * c;
  });
  const std::vector<int> tetOrder = hilbertOrder(centroids);
  std::vector<std::array<int, 4>> sorted(tets.size());
  for (std::size_t k = 0; k < tets.size(); ++k) sorted[k] = tets[tetOrder[k]];
  tets = std::move(sorted);
}

}  // namespace tfd::core
