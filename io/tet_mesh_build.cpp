#include "io/tet_mesh_build.h"

#include <algorithm>

#include "core/error.h"

namespace tfd::io {

std::shared_ptr<const core::TetMesh> buildTetMesh(std::vector<core::Vec3> positions,
                                                  std::vector<core::TetMesh::Tet> tets,
                                                  const std::string& source,
                                                  const core::Progress& progress) {
  const int n = int(positions.size());
  bool inRange = true;
  for (const auto& t : tets) {
    for (int v : t) inRange &= v >= 0 && v < n;
  }
  if (inRange && !tets.empty()) {
    // Drop unused vertices.
    std::vector<int> map(n, -1);
    for (const auto& t : tets) {
      for (int v : t) map[v] = 0;
    }
    if (std::count(map.begin(), map.end(), -1) > 0) {
      int next = 0;
      for (int v = 0; v < n; ++v) {
        if (map[v] == 0) {
          positions[next] = positions[v];
          map[v] = next++;
        }
      }
      positions.resize(next);
      for (auto& t : tets) {
        for (int& v : t) v = map[v];
      }
    }
    // A consistently inverted mesh is a convention, not an error: flip it.
    const bool allNegative = std::all_of(tets.begin(), tets.end(), [&](const auto& t) {
      return core::signedVolume(positions[t[0]], positions[t[1]], positions[t[2]],
                                positions[t[3]]) < 0;
    });
    if (allNegative) {
      for (auto& t : tets) std::swap(t[1], t[2]);
    }
  }
  try {
    return std::make_shared<const core::TetMesh>(std::move(positions), std::move(tets), progress);
  } catch (const core::Cancelled&) {
    throw;
  } catch (const core::Error& e) {
    throw core::Error(source + ": " + e.what());
  }
}

}  // namespace tfd::io
