#pragma once
// Per tet, filled on first use: its face neighbours and its centroid in one 40-byte row, for
// the hot loops of region growing (ball_region.h, tet_set.h). A row replaces tetFaces() then
// faceTets() per face (dependent cache misses) and the tet's corners; filling on demand keeps
// the cost proportional to the tets reached, not to the mesh (one flag byte per mesh tet; the
// rows' pages are never touched for tets not reached). Not thread-safe (the growth is
// sequential).
#include <array>
#include <memory>
#include <vector>

#include "core/tet_mesh.h"

namespace tfd::core {

class TetRows {
 public:
  struct Row {
    Vec3 centroid;
    std::array<int, 4> neighbours;  ///< across the face opposite local vertex i; −1: surface
  };
  explicit TetRows(const TetMesh& mesh)
      : mesh_(mesh), rows_(new Row[mesh.tetCount()]), known_(mesh.tetCount(), 0) {}

  const Row& operator[](int tet) const {
    if (!known_[tet]) fill(tet);
    return rows_[tet];
  }
  /// Starts loading tet's row (a hint: a loop that knows its next tet hides the cache miss
  /// behind the current one's work).
  void prefetch(int tet) const {
    __builtin_prefetch(&known_[tet]);
    __builtin_prefetch(&rows_[tet]);
  }

 private:
  void fill(int tet) const {
    Row& r = rows_[tet];
    const auto& v = mesh_.tets()[tet];
    const auto& p = mesh_.positions();
    r.centroid = 0.25 * (p[v[0]] + p[v[1]] + p[v[2]] + p[v[3]]);
    for (int i = 0; i < 4; ++i) {
      const auto& ft = mesh_.faceTets()[mesh_.tetFaces()[tet][i]];
      r.neighbours[i] = ft[0] == tet ? ft[1] : ft[0];
    }
    known_[tet] = 1;
  }

  const TetMesh& mesh_;
  std::unique_ptr<Row[]> rows_;
  mutable std::vector<unsigned char> known_;
};

}  // namespace tfd::core
