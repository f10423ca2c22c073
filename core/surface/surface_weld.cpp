#include "core/surface/surface_weld.h"

#include <array>
#include <cstdint>
#include <cstring>
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

}  // namespace

WeldReport weldCoincidentVertices(SurfaceMesh& mesh) {
  WeldReport report;
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

}  // namespace tfd::core
