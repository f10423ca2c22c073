// TetMesh construction: fast validity checks, vertex-to-tet incidence, edges and faces.
//
// Edges and faces are numbered in lexicographic order of their sorted vertex ids, which is
// what one global sort of all (key, slot) records gives. Instead of sorting 6 × tets edge
// records and 4 × tets face records globally, each vertex a collects the edges and faces whose
// lowest vertex is a from its incident tets (a few dozen records), sorts them locally, and a
// prefix sum over vertices turns local ranks into global ids: the same numbering, in parallel
// over vertices with cache-local work. Every output entry is written by exactly one task, so
// the result is bitwise the same for any thread count.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>

#include "core/tet_mesh.h"
#include "core/tet_mesh_local.h"

namespace tfd::core {
namespace {

using tet_local::kEdge;
using tet_local::kFace;

constexpr std::size_t kVertexGrain = 2048;
/// Tet blocks of the incidence build (fixed, independent of the thread count).
constexpr std::size_t kIncidenceBlocks = 8;

/// Local edge index (into kEdge) of the local vertex pair (i, j), i != j.
constexpr int edgeIndex(int i, int j) {
  if (i > j) std::swap(i, j);
  return i == 0 ? j - 1 : (i == 1 ? j + 1 : 5);
}

/// Edge record of vertex a: the other (higher) vertex and the slot t * 6 + local edge.
using EdgeRecord = std::uint64_t;  // (b << 32) | slot

/// Face record of vertex a: the other two vertices (sorted) and the slot t * 4 + local face.
struct FaceRecord {
  std::uint64_t key;  // (b << 32) | c, b < c
  std::uint32_t slot;
  bool operator<(const FaceRecord& o) const { return key != o.key ? key < o.key : slot < o.slot; }
};

/// The records whose lowest vertex is `a`, sorted (by key, then by slot: lower tet first).
void collect(const std::vector<TetMesh::Tet>& tets, std::span<const int> incident, int a,
             std::vector<EdgeRecord>& edges, std::vector<FaceRecord>& faces) {
  edges.clear();
  faces.clear();
  for (int t : incident) {
    const auto& tet = tets[t];
    int i = 0;
    while (tet[i] != a) ++i;
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      if (tet[j] > a)
        edges.push_back(std::uint64_t(tet[j]) << 32 | std::uint32_t(t * 6 + edgeIndex(i, j)));
      // The face opposite j contains a; keep it when a is its lowest vertex.
      int b = -1, c = -1;
      for (int k : kFace[j]) {
        if (k == i) continue;
        (b < 0 ? b : c) = tet[k];
      }
      if (b < a || c < a) continue;
      if (b > c) std::swap(b, c);
      faces.push_back({std::uint64_t(b) << 32 | std::uint32_t(c), std::uint32_t(t * 4 + j)});
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(faces.begin(), faces.end());
}

}  // namespace

bool TetMesh::quickCheckAndVolumes() {
  const int n = static_cast<int>(positions_.size());
  if (tets_.empty()) return false;
  std::atomic<bool> ok = true;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, positions_.size(), 4096),
                    [&](const auto& r) {
                      for (std::size_t v = r.begin(); v != r.end(); ++v)
                        if (!positions_[v].allFinite()) ok = false;
                    });
  volumes_.resize(tets_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tets_.size(), 4096), [&](const auto& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& tet = tets_[t];
      bool valid = true;
      for (int i = 0; i < 4; ++i) valid &= tet[i] >= 0 && tet[i] < n;
      for (const auto& e : kEdge) valid &= !valid || tet[e[0]] != tet[e[1]];
      if (valid) valid = tet_local::volumeOk(positions_, tet, volumes_[t]);
      if (!valid) ok.store(false, std::memory_order_relaxed);
    }
  });
  return ok;
}

bool TetMesh::buildIncidence(const Progress& progress) {
  // A counting sort in a fixed number of tet blocks (not one per thread, so the result does
  // not depend on the threads): each block counts its uses of every vertex, offsets run
  // vertex by vertex through the blocks in order, and each block writes its tets in order, so
  // every vertex's list comes out ascending with no atomics and no sort.
  const std::size_t nv = positions_.size(), nt = tets_.size();
  const std::size_t blockSize = (nt + kIncidenceBlocks - 1) / kIncidenceBlocks;
  std::vector<int> slots(kIncidenceBlocks * nv, 0);  // block b's count, then offset, of v
  tbb::parallel_for(std::size_t(0), kIncidenceBlocks, [&](std::size_t b) {
    if (progress.cancelled()) return;
    int* mine = slots.data() + b * nv;
    for (std::size_t t = b * blockSize; t < std::min(nt, (b + 1) * blockSize); ++t)
      for (int v : tets_[t]) ++mine[v];
  });
  progress.throwIfCancelled();
  vertexTetStart_.resize(nv + 1);
  int running = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    vertexTetStart_[v] = running;
    for (std::size_t b = 0; b < kIncidenceBlocks; ++b) {
      const int count = slots[b * nv + v];
      slots[b * nv + v] = running;
      running += count;
    }
    if (running == vertexTetStart_[v]) return false;  // a vertex no tet uses
  }
  vertexTetStart_[nv] = running;
  vertexTetIds_.resize(std::size_t(running));
  tbb::parallel_for(std::size_t(0), kIncidenceBlocks, [&](std::size_t b) {
    if (progress.cancelled()) return;
    int* next = slots.data() + b * nv;
    for (std::size_t t = b * blockSize; t < std::min(nt, (b + 1) * blockSize); ++t)
      for (int v : tets_[t]) vertexTetIds_[next[v]++] = static_cast<int>(t);
  });
  progress.throwIfCancelled();
  return true;
}

bool TetMesh::buildEdgesAndFaces(const Progress& progress) {
  const std::size_t nv = positions_.size(), nt = tets_.size();
  // Pass 1: how many distinct edges and faces have each vertex as their lowest; a face with
  // more than two tets makes the mesh non-manifold.
  std::vector<int> edgeStart(nv + 1, 0), faceStart(nv + 1, 0);
  std::atomic<bool> manifold = true;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kVertexGrain), [&](const auto& r) {
    if (progress.cancelled()) return;
    std::vector<EdgeRecord> edges;
    std::vector<FaceRecord> faces;
    for (std::size_t a = r.begin(); a != r.end(); ++a) {
      collect(tets_, vertexTets(static_cast<int>(a)), static_cast<int>(a), edges, faces);
      int edgeCount = 0, faceCount = 0;
      for (std::size_t i = 0; i < edges.size(); ++i)
        edgeCount += i == 0 || (edges[i] >> 32) != (edges[i - 1] >> 32);
      for (std::size_t i = 0; i < faces.size(); ++i) {
        faceCount += i == 0 || faces[i].key != faces[i - 1].key;
        if (i >= 2 && faces[i].key == faces[i - 2].key) manifold = false;
      }
      edgeStart[a + 1] = edgeCount;
      faceStart[a + 1] = faceCount;
    }
  });
  progress.throwIfCancelled();
  if (!manifold) return false;
  for (std::size_t v = 0; v < nv; ++v) {
    edgeStart[v + 1] += edgeStart[v];
    faceStart[v + 1] += faceStart[v];
  }
  // Pass 2: the same records again, written at their global ids.
  edges_.resize(edgeStart[nv]);
  faces_.resize(faceStart[nv]);
  faceTets_.resize(faceStart[nv]);
  tetEdges_.resize(nt);
  tetFaces_.resize(nt);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kVertexGrain), [&](const auto& r) {
    if (progress.cancelled()) return;
    std::vector<EdgeRecord> edges;
    std::vector<FaceRecord> faces;
    for (std::size_t a = r.begin(); a != r.end(); ++a) {
      const int va = static_cast<int>(a);
      collect(tets_, vertexTets(va), va, edges, faces);
      int id = edgeStart[a] - 1;
      for (std::size_t i = 0; i < edges.size(); ++i) {
        const int b = static_cast<int>(edges[i] >> 32);
        if (i == 0 || (edges[i - 1] >> 32) != (edges[i] >> 32)) edges_[++id] = {va, b};
        const std::uint32_t slot = edges[i] & 0xffffffffu;
        tetEdges_[slot / 6][slot % 6] = id;
      }
      id = faceStart[a] - 1;
      for (std::size_t i = 0; i < faces.size(); ++i) {
        const int t = static_cast<int>(faces[i].slot / 4);
        if (i == 0 || faces[i - 1].key != faces[i].key) {
          faces_[++id] = {va, static_cast<int>(faces[i].key >> 32),
                          static_cast<int>(faces[i].key & 0xffffffffu)};
          faceTets_[id] = {t, -1};
        } else {
          faceTets_[id][1] = t;
        }
        tetFaces_[t][faces[i].slot % 4] = id;
      }
    }
  });
  return true;
}

void TetMesh::buildSummaries() {
  // Serial sums in index order: the same bits as ever, for any thread count.
  totalVolume_ = 0;
  for (double v : volumes_) totalVolume_ += v;
  boundsMin_ = boundsMax_ = positions_[0];
  for (const auto& p : positions_) {
    boundsMin_ = boundsMin_.cwiseMin(p);
    boundsMax_ = boundsMax_.cwiseMax(p);
  }
  std::vector<double> lengths(edges_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges_.size(), 8192), [&](const auto& r) {
    for (std::size_t e = r.begin(); e != r.end(); ++e)
      lengths[e] = (positions_[edges_[e][0]] - positions_[edges_[e][1]]).norm();
  });
  double lengthSum = 0;
  for (double l : lengths) lengthSum += l;
  meanEdgeLength_ = edges_.empty() ? 0 : lengthSum / static_cast<double>(edges_.size());
}

}  // namespace tfd::core
