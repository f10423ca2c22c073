#include "core/surface/surface_holes.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace tfd::core {

std::vector<std::vector<int>> holeLoops(const SurfaceMesh& mesh) {
  // Half-edges by (from, to); an open one has no reverse twin.
  std::vector<std::uint64_t> half;
  half.reserve(3 * mesh.triangles.size());
  auto key = [](int a, int b) { return std::uint64_t(std::uint32_t(a)) << 32 | std::uint32_t(b); };
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) half.push_back(key(t[k], t[(k + 1) % 3]));
  std::sort(half.begin(), half.end());
  // A filling triangle runs an open half-edge a → b backwards: b → a.
  std::vector<int> next(mesh.positions.size(), -1);
  std::vector<int> boundary;
  for (std::uint64_t h : half) {
    const int a = int(h >> 32), b = int(h & 0xffffffffu);
    if (std::binary_search(half.begin(), half.end(), key(b, a))) continue;
    if (next[b] >= 0) return {};  // b starts two open edges
    next[b] = a;
    boundary.push_back(b);
  }
  std::sort(boundary.begin(), boundary.end());
  std::vector<std::vector<int>> loops;
  std::vector<char> seen(mesh.positions.size(), 0);
  for (int start : boundary) {
    if (seen[start]) continue;
    std::vector<int> loop;
    for (int v = start; !seen[v]; v = next[v]) {
      if (next[v] < 0) return {};  // an open chain that does not close
      seen[v] = 1;
      loop.push_back(v);
    }
    if (next[loop.back()] != start) return {};  // ran into another loop
    loops.push_back(std::move(loop));
  }
  return loops;
}

HoleFilling fillHoles(SurfaceMesh& mesh, std::size_t maxEdges) {
  HoleFilling r;
  for (const auto& loop : holeLoops(mesh)) {
    r.largest = std::max(r.largest, loop.size());
    if (loop.size() > maxEdges) {
      ++r.skipped;
      continue;
    }
    ++r.filled;
    const std::size_t n = loop.size();
    if (n == 3) {
      mesh.triangles.push_back({loop[0], loop[1], loop[2]});
      ++r.triangles;
      continue;
    }
    Vec3 centre = Vec3::Zero();
    for (int v : loop) centre += mesh.positions[v];
    const int c = int(mesh.positions.size());
    mesh.positions.push_back(centre / double(n));
    for (std::size_t i = 0; i < n; ++i) mesh.triangles.push_back({loop[i], loop[(i + 1) % n], c});
    r.triangles += n;
  }
  return r;
}

}  // namespace tfd::core
