// TetMesh construction: fast validity checks, vertex-to-tet incidence, edges and faces.
//
// Edges and faces are numbered in lexicographic order of their sorted vertex ids, which is
// what one global sort of all (key, slot) records gives. Instead of sorting 6 × tets edge
// records and 4 × tets face records globally, each vertex a collects the edges and faces whose
// lowest vertex is a from its incident tets (a few dozen records) and sorts them locally. One
// pass over fixed chunks of vertices numbers them inside each chunk (and lists each chunk's
// edges and faces); a prefix sum over chunks then gives the global ids, and a sequential pass
// over the tets shifts their ids by their chunk's offset: the same numbering, in parallel,
// collecting each vertex's records once. Every output entry is written by exactly one task,
// so the result is bitwise the same for any thread count.
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
constexpr int kChunk = static_cast<int>(kVertexGrain);
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

/// The records whose lowest vertex is `a`, sorted (by key, then by slot: lower tet first);
/// `incident` are a's tets (ids ascending) and `tets` their vertices.
void collect(std::span<const TetMesh::Tet> tets, std::span<const int> incident, int a,
             std::vector<EdgeRecord>& edges, std::vector<FaceRecord>& faces) {
  edges.clear();
  faces.clear();
  for (std::size_t k = 0; k < incident.size(); ++k) {
    const int t = incident[k];
    const auto& tet = tets[k];
    int i = 0;
    while (tet[i] != a) ++i;
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      if (tet[j] > a)
        edges.push_back(std::uint64_t(tet[j]) << 32 | std::uint32_t(t * 6 + edgeIndex(i, j)));
      // The face opposite j contains a; keep it when a is its lowest vertex.
      int b = -1, c = -1;
      for (int m : kFace[j]) {
        if (m == i) continue;
        (b < 0 ? b : c) = tet[m];
      }
      if (b < a || c < a) continue;
      if (b > c) std::swap(b, c);
      faces.push_back({std::uint64_t(b) << 32 | std::uint32_t(c), std::uint32_t(t * 4 + j)});
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(faces.begin(), faces.end());
}

/// What the first pass leaves for one chunk of vertices: the distinct edges and faces whose
/// lowest vertex is in the chunk, in their global order, and each face's tets.
struct Chunk {
  std::vector<TetMesh::Edge> edges;
  std::vector<TetMesh::Face> faces;
  std::vector<std::array<int, 2>> faceTets;
};

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
  const std::size_t chunkCount = (nv + kVertexGrain - 1) / kVertexGrain;
  // Pass 1, per fixed chunk of vertices: each vertex's records, sorted; the chunk's distinct
  // edges and faces appended in order, and every tet slot given its id inside the chunk. A
  // face with more than two tets makes the mesh non-manifold.
  std::vector<Chunk> chunks(chunkCount);
  tetEdges_.resize(nt);
  tetFaces_.resize(nt);
  std::atomic<bool> manifold = true;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunkCount, 1), [&](const auto& r) {
    std::vector<EdgeRecord> edges;
    std::vector<FaceRecord> faces;
    std::vector<Tet> local;
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      if (progress.cancelled()) return;
      Chunk& out = chunks[c];
      const std::size_t begin = c * kVertexGrain, end = std::min(nv, begin + kVertexGrain);
      // The chunk's incident tets gathered first (independent loads the processor overlaps;
      // TetGen's tet ids have no spatial order), so the collection below reads them in order.
      const int first = vertexTetStart_[begin];
      local.resize(std::size_t(vertexTetStart_[end] - first));
      for (std::size_t k = 0; k < local.size(); ++k) local[k] = tets_[vertexTetIds_[first + k]];
      out.edges.reserve((end - begin) * 8);
      out.faces.reserve((end - begin) * 14);
      out.faceTets.reserve((end - begin) * 14);
      for (std::size_t a = begin; a != end; ++a) {
        const int va = static_cast<int>(a);
        const std::span<const int> incident = vertexTets(va);
        collect(std::span<const Tet>(local).subspan(std::size_t(vertexTetStart_[a] - first),
                                                    incident.size()),
                incident, va, edges, faces);
        int id = static_cast<int>(out.edges.size()) - 1;
        for (std::size_t i = 0; i < edges.size(); ++i) {
          if (i == 0 || (edges[i - 1] >> 32) != (edges[i] >> 32))
            out.edges.push_back({va, static_cast<int>(edges[i] >> 32)}), ++id;
          const std::uint32_t slot = edges[i] & 0xffffffffu;
          tetEdges_[slot / 6][slot % 6] = id;
        }
        id = static_cast<int>(out.faces.size()) - 1;
        for (std::size_t i = 0; i < faces.size(); ++i) {
          const int t = static_cast<int>(faces[i].slot / 4);
          if (i == 0 || faces[i - 1].key != faces[i].key) {
            out.faces.push_back({va, static_cast<int>(faces[i].key >> 32),
                                 static_cast<int>(faces[i].key & 0xffffffffu)});
            out.faceTets.push_back({t, -1});
            ++id;
          } else if (out.faceTets[id][1] >= 0) {
            manifold.store(false, std::memory_order_relaxed);
          } else {
            out.faceTets[id][1] = t;
          }
          tetFaces_[t][faces[i].slot % 4] = id;
        }
      }
    }
  });
  progress.throwIfCancelled();
  if (!manifold) return false;
  // Chunk offsets, then pass 2: the chunks' lists concatenated, and every tet's ids shifted
  // by the offset of the chunk owning the edge or face (its lowest vertex's chunk).
  std::vector<int> edgeStart(chunkCount + 1, 0), faceStart(chunkCount + 1, 0);
  for (std::size_t c = 0; c < chunkCount; ++c) {
    edgeStart[c + 1] = edgeStart[c] + static_cast<int>(chunks[c].edges.size());
    faceStart[c + 1] = faceStart[c] + static_cast<int>(chunks[c].faces.size());
  }
  edges_.resize(std::size_t(edgeStart[chunkCount]));
  faces_.resize(std::size_t(faceStart[chunkCount]));
  faceTets_.resize(std::size_t(faceStart[chunkCount]));
  tbb::parallel_for(std::size_t(0), chunkCount, [&](std::size_t c) {
    Chunk& in = chunks[c];
    std::copy(in.edges.begin(), in.edges.end(), edges_.begin() + edgeStart[c]);
    std::copy(in.faces.begin(), in.faces.end(), faces_.begin() + faceStart[c]);
    std::copy(in.faceTets.begin(), in.faceTets.end(), faceTets_.begin() + faceStart[c]);
    in = Chunk{};
  });
  progress.throwIfCancelled();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 8192), [&](const auto& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& tet = tets_[t];
      for (int e = 0; e < 6; ++e)
        tetEdges_[t][e] += edgeStart[std::min(tet[kEdge[e][0]], tet[kEdge[e][1]]) / kChunk];
      for (int j = 0; j < 4; ++j) {
        const auto& f = kFace[j];
        const int low = std::min({tet[f[0]], tet[f[1]], tet[f[2]]});
        tetFaces_[t][j] += faceStart[low / kChunk];
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
