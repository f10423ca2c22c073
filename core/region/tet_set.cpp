#include "core/region/tet_set.h"

#include <algorithm>

namespace tfd::core {
namespace {

/// Local vertices of the tet's edges in TetMesh::tetEdges() order (01, 02, 03, 12, 13, 23).
constexpr int kEdgeEnds[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
/// Position in that order of the edge joining local vertices i and j.
constexpr int kEdgeOf[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

/// Tets around the edge (a, b): those around a that also hold b.
int countTetsAround(const TetMesh& mesh, const TetMesh::Edge& ends) {
  int n = 0;
  for (int t : mesh.vertexTets(ends[0])) {
    const auto& v = mesh.tets()[t];
    n += (v[0] == ends[1]) | (v[1] == ends[1]) | (v[2] == ends[1]) | (v[3] == ends[1]);
  }
  return n;
}

}  // namespace

TetSet::TetSet(const TetMesh& mesh)
    : mesh_(mesh),
      rows_(mesh),
      in_(mesh.tetCount(), 0),
      vertexCount_(mesh.vertexCount(), 0),
      edgeCount_(mesh.edges().size(), 0),
      edgeTets_(mesh.edges().size(), -1),
      edgeOnSurface_(mesh.edges().size(), 0) {
  for (int f : mesh.boundaryFaces()) {
    const int t = mesh.faceTets()[f][0];
    for (int i = 0; i < 4; ++i) {
      if (mesh.tetFaces()[t][i] != f) continue;
      for (int e = 0; e < 6; ++e)  // the face opposite vertex i holds the edges without i
        if (kEdgeEnds[e][0] != i && kEdgeEnds[e][1] != i) edgeOnSurface_[mesh.tetEdges()[t][e]] = 1;
    }
  }
}

// Counted on first use, so a set costs in proportion to the tets it touches rather than to
// the mesh.
int TetSet::tetsAround(int edge) const {
  int& n = edgeTets_[edge];
  if (n < 0) n = countTetsAround(mesh_, mesh_.edges()[edge]);
  return n;
}

void TetSet::countAllEdges() const {
  std::fill(edgeTets_.begin(), edgeTets_.end(), 0);
  for (const auto& edges : mesh_.tetEdges())
    for (int e : edges) ++edgeTets_[e];
}

int TetSet::sharedFaces(int tet) const {
  int n = 0;
  for (int other : neighbours(tet)) n += other >= 0 && in_[other] != 0;
  return n;
}

namespace {

/// Whether the part of ∂t made of the faces `face[i]` (opposite local vertex i; `count` of
/// them) is a disk that holds every vertex and edge of t found held elsewhere. Three faces
/// hold every vertex and edge; one face (opposite i) all but vertex i and its edges; two
/// (opposite i and j) all but edge ij. So one count decides: `vertexHeld(i)` or
/// `edgeHeld(local edge)` (an edge at vertex i held elsewhere means a tet holding i).
template <class VertexHeld, class EdgeHeld>
bool faceContactIsDisk(const bool face[4], int count, VertexHeld&& vertexHeld,
                       EdgeHeld&& edgeHeld) {
  if (count == 3) return true;
  if (count == 1) {
    int i = 0;
    while (!face[i]) ++i;
    return !vertexHeld(i);
  }
  if (count == 2) {
    int i = 0;
    while (!face[i]) ++i;
    int j = i + 1;
    while (!face[j]) ++j;
    return !edgeHeld(kEdgeOf[i][j]);
  }
  return false;  // no face, or all four (a closed sphere)
}

}  // namespace

// `self` is 1 when the tet itself is counted in the occupancy (removal), 0 otherwise.
bool TetSet::contactIsDisk(int tet, int self) const {
  bool faceShared[4];  // face opposite local vertex i
  int shared = 0;
  for (int i = 0; i < 4; ++i) {
    const int other = neighbours(tet)[i];
    faceShared[i] = other >= 0 && in_[other] != 0;
    shared += faceShared[i];
  }
  return faceContactIsDisk(
      faceShared, shared, [&](int i) { return vertexCount_[mesh_.tets()[tet][i]] - self != 0; },
      [&](int e) { return edgeCount_[mesh_.tetEdges()[tet][e]] - self != 0; });
}

// For a member tet: its contact with everything outside the set (other tets not in the set,
// and the outside of the domain through surface faces, edges and vertices) must be a disk.
bool TetSet::complementContactIsDisk(int tet) const {
  bool faceOut[4];
  int out = 0;
  for (int i = 0; i < 4; ++i) {
    const int other = neighbours(tet)[i];
    faceOut[i] = other < 0 || in_[other] == 0;
    out += faceOut[i];
  }
  return faceContactIsDisk(
      faceOut, out,
      [&](int i) {
        const int v = mesh_.tets()[tet][i];
        return mesh_.isBoundaryVertex(v) || int(mesh_.vertexTets(v).size()) > vertexCount_[v];
      },
      [&](int e) {
        const int id = mesh_.tetEdges()[tet][e];
        return edgeOnSurface_[id] || tetsAround(id) != edgeCount_[id];
      });
}

bool TetSet::canAdd(int tet) const {
  if (size_ == 0) return true;
  return !contains(tet) && contactIsDisk(tet, 0);
}

bool TetSet::canRemove(int tet) const {
  if (size_ <= 1 || !contains(tet)) return false;
  return contactIsDisk(tet, 1) && complementContactIsDisk(tet);
}

void TetSet::add(int tet) {
  if (in_[tet]) return;
  in_[tet] = 1;
  ++size_;
  for (int v : mesh_.tets()[tet]) ++vertexCount_[v];
  for (int e : mesh_.tetEdges()[tet]) ++edgeCount_[e];
}

void TetSet::remove(int tet) {
  if (!in_[tet]) return;
  in_[tet] = 0;
  --size_;
  for (int v : mesh_.tets()[tet]) --vertexCount_[v];
  for (int e : mesh_.tetEdges()[tet]) --edgeCount_[e];
}

std::vector<int> TetSet::tets() const {
  std::vector<int> out;
  out.reserve(size_);
  for (std::size_t t = 0; t < in_.size(); ++t)
    if (in_[t]) out.push_back(static_cast<int>(t));
  return out;
}

}  // namespace tfd::core
