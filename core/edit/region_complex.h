#pragma once
// The simplicial complex of a region of tets (paper §6: the region M of an edit): its tets,
// vertices and edges, numbered locally, with the vertex adjacency of the region's edges.
//
// Input: a mesh and tet ids (any order, repeats allowed). Output: ascending unique tets,
// vertices and mesh edge ids; local indices are positions in those lists. Lookups from mesh
// ids to local ones are O(1) through tables of one int per mesh vertex, edge and tet (about
// 10 MB at 1M tets, filled at memset speed); everything else costs in proportion to the region.
// Deterministic (no parallelism: the lists are sorted).
#include <vector>

#include "core/tet_mesh.h"

namespace tfd::core {

struct RegionComplex {
  std::vector<int> tets;      ///< ascending mesh tet ids
  std::vector<int> vertices;  ///< ascending mesh vertex ids of the tets
  std::vector<int> edges;     ///< ascending mesh edge ids of the tets
  /// Adjacency of local vertices through region edges (CSR): neighbours of local vertex i are
  /// neighbour[start[i] .. start[i+1]), ascending, and neighbourEdge the local edge joining them.
  std::vector<int> start, neighbour, neighbourEdge;

  /// −1 when not in the region (inline: the hot loops of §6.3 look up every neighbour).
  int localVertex(int meshVertex) const { return lookup(vertexLocal, meshVertex); }
  int localEdge(int meshEdge) const { return lookup(edgeLocal, meshEdge); }
  int localTet(int meshTet) const { return lookup(tetLocal, meshTet); }
  /// Number of connected pieces of the vertex graph (0 for an empty region).
  int components() const;

  /// Local index per mesh vertex / edge / tet (−1 outside); filled by regionComplex().
  std::vector<int> vertexLocal, edgeLocal, tetLocal;

 private:
  static int lookup(const std::vector<int>& table, int id) {
    return id >= 0 && static_cast<std::size_t>(id) < table.size() ? table[id] : -1;
  }
};

/// Throws core::Error when `tets` is empty or holds an id that is not a tet of `mesh`.
RegionComplex regionComplex(const TetMesh& mesh, const std::vector<int>& tets);

/// The local edge joining local vertices a and b (−1 when they share no region edge).
int regionEdge(const RegionComplex& region, int localA, int localB);

}  // namespace tfd::core
