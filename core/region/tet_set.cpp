#include "core/region/tet_set.h"

namespace tfd::core {
namespace {

/// Local vertices of the tet's edges in TetMesh::tetEdges() order (01, 02, 03, 12, 13, 23).
constexpr int kEdgeEnds[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

}  // namespace

TetSet::TetSet(const TetMesh& mesh)
    : mesh_(mesh),
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

// Tets around an edge: those around both ends (sorted lists), counted on first use, so a
// set costs in proportion to the tets it touches rather than to the mesh.
int TetSet::tetsAround(int edge) const {
  int& n = edgeTets_[edge];
  if (n < 0) {
    const auto& ends = mesh_.edges()[edge];
    const auto a = mesh_.vertexTets(ends[0]), b = mesh_.vertexTets(ends[1]);
    n = 0;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
      if (a[i] < b[j]) {
        ++i;
      } else if (b[j] < a[i]) {
        ++j;
      } else {
        ++n, ++i, ++j;
      }
    }
  }
  return n;
}

int TetSet::sharedFaces(int tet) const {
  int n = 0;
  for (int f : mesh_.tetFaces()[tet]) {
    const auto& ft = mesh_.faceTets()[f];
    const int other = ft[0] == tet ? ft[1] : ft[0];
    n += other >= 0 && in_[other] != 0;
  }
  return n;
}

// `self` is 1 when the tet itself is counted in the occupancy (removal), 0 otherwise.
bool TetSet::contactIsDisk(int tet, int self) const {
  bool faceShared[4];  // face opposite local vertex i
  int shared = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& ft = mesh_.faceTets()[mesh_.tetFaces()[tet][i]];
    const int other = ft[0] == tet ? ft[1] : ft[0];
    faceShared[i] = other >= 0 && in_[other] != 0;
    shared += faceShared[i];
  }
  if (shared == 0 || shared == 4) return false;
  const auto& verts = mesh_.tets()[tet];
  for (int i = 0; i < 4; ++i) {
    if (vertexCount_[verts[i]] - self == 0) continue;
    // The faces holding vertex i are those opposite the other three vertices.
    bool covered = false;
    for (int j = 0; j < 4; ++j) covered = covered || (j != i && faceShared[j]);
    if (!covered) return false;
  }
  for (int e = 0; e < 6; ++e) {
    if (edgeCount_[mesh_.tetEdges()[tet][e]] - self == 0) continue;
    // The faces holding edge (a, b) are those opposite its two other vertices.
    const int a = kEdgeEnds[e][0], b = kEdgeEnds[e][1];
    bool covered = false;
    for (int j = 0; j < 4; ++j) covered = covered || (j != a && j != b && faceShared[j]);
    if (!covered) return false;
  }
  return true;
}

// For a member tet: its contact with everything outside the set (other tets not in the set,
// and the outside of the domain through surface faces, edges and vertices) must be a disk.
bool TetSet::complementContactIsDisk(int tet) const {
  bool faceOut[4];
  int out = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& ft = mesh_.faceTets()[mesh_.tetFaces()[tet][i]];
    const int other = ft[0] == tet ? ft[1] : ft[0];
    faceOut[i] = other < 0 || in_[other] == 0;
    out += faceOut[i];
  }
  if (out == 0 || out == 4) return false;
  const auto& verts = mesh_.tets()[tet];
  for (int i = 0; i < 4; ++i) {
    const int v = verts[i];
    const bool touched =
        mesh_.isBoundaryVertex(v) || int(mesh_.vertexTets(v).size()) > vertexCount_[v];
    if (!touched) continue;
    bool covered = false;
    for (int j = 0; j < 4; ++j) covered = covered || (j != i && faceOut[j]);
    if (!covered) return false;
  }
  for (int e = 0; e < 6; ++e) {
    const int id = mesh_.tetEdges()[tet][e];
    if (!edgeOnSurface_[id] && tetsAround(id) == edgeCount_[id]) continue;
    const int a = kEdgeEnds[e][0], b = kEdgeEnds[e][1];
    bool covered = false;
    for (int j = 0; j < 4; ++j) covered = covered || (j != a && j != b && faceOut[j]);
    if (!covered) return false;
  }
  return true;
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
