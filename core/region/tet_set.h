#pragma once
// A set of tets that stays a topological ball while it grows or shrinks one tet at a time
// (paper §6.1, "a topology-aware morphological dilation and erosion"), by the classic
// simple-tet test: a tet may join (or leave) the set when its contact with the rest of the set
// is a closed disk. Then the union before and after are homeomorphic, so a ball stays a ball.
// Removal also needs the tet's contact with the complement (the tets outside the set and the
// space outside the domain) to be a disk: otherwise the hole left behind can pinch the set at a
// vertex or edge that the complement already touches elsewhere.
//
// The contact of tet t with the union |S| of the other tets is a subcomplex of ∂t (a simplicial
// mesh: two simplices meet in a common face). It is a disk exactly when it is pure 2-D: one, two
// or three faces of t are shared with tets of S, and every edge and vertex of t that some tet of
// S holds lies on one of those faces. Edge and vertex occupancy counts make the test O(1).
// Memory: a few bytes per tet, edge and vertex of the mesh.
#include <array>
#include <cstddef>
#include <vector>

#include "core/region/tet_rows.h"
#include "core/tet_mesh.h"

namespace tfd::core {

class TetSet {
 public:
  explicit TetSet(const TetMesh& mesh);

  const TetMesh& mesh() const { return mesh_; }
  bool contains(int tet) const { return in_[tet] != 0; }
  /// Starts loading what canAdd(tet) / contains(tet) read first (a hint, see TetRows).
  void prefetch(int tet) const {
    __builtin_prefetch(&in_[tet]);
    rows_.prefetch(tet);
    __builtin_prefetch(&mesh_.tets()[tet]);      // the simple-tet test's corners
    __builtin_prefetch(&mesh_.tetEdges()[tet]);  // or edges
  }
  /// The second stage, once prefetch(tet) has had time to land: starts loading what the tests
  /// read through the tet's corners, edges and neighbours (a loop that knows its order ahead,
  /// as the shrink does, calls it a few tets before `tet`).
  void prefetchAround(int tet) const {
    for (int v : mesh_.tets()[tet]) __builtin_prefetch(&vertexCount_[v]);
    for (int e : mesh_.tetEdges()[tet]) {
      __builtin_prefetch(&edgeCount_[e]);
      __builtin_prefetch(&edgeTets_[e]);
    }
    for (int n : rows_[tet].neighbours)
      if (n >= 0) __builtin_prefetch(&in_[n]);
  }
  std::size_t size() const { return size_; }
  /// Whether adding `tet` (not in the set) keeps a ball a ball; true for an empty set.
  bool canAdd(int tet) const;
  /// Whether removing `tet` (in the set) keeps a ball a ball; false for the last tet.
  bool canRemove(int tet) const;
  /// Counts the tets around every edge of the mesh in one pass over its tets, instead of edge
  /// by edge when canRemove() first asks (a scan of the tets around one end): for a shrink of
  /// a large part of the mesh.
  void countAllEdges() const;
  /// Adds / removes without testing (the caller tests first when it must keep a ball).
  void add(int tet);
  void remove(int tet);
  /// Number of the tet's four faces shared with tets of the set (itself excluded).
  int sharedFaces(int tet) const;
  /// The member tets, ascending. O(mesh tets).
  std::vector<int> tets() const;
  /// The tet across the face opposite local vertex i of `tet` (−1 on the domain surface).
  const std::array<int, 4>& neighbours(int tet) const { return rows_[tet].neighbours; }
  /// Neighbours and centroids of every tet (shared with the distance fronts).
  const TetRows& rows() const { return rows_; }

 private:
  bool contactIsDisk(int tet, int self) const;
  bool complementContactIsDisk(int tet) const;

  const TetMesh& mesh_;
  TetRows rows_;
  std::vector<unsigned char> in_;
  std::vector<int> vertexCount_, edgeCount_;
  int tetsAround(int edge) const;
  mutable std::vector<int> edgeTets_;         ///< tets around each edge, −1 until needed
  std::vector<unsigned char> edgeOnSurface_;  ///< edge of a domain-surface face
  std::size_t size_ = 0;
};

}  // namespace tfd::core
