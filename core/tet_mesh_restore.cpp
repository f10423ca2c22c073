// TetMesh restored from stored topology ids (the on-disk cook cache): edges and faces are
// read off tetEdges and tetFaces instead of being sorted again, then everything is verified.
//
// Why the checks prove the result identical to a fresh build (core/tet_mesh_topology.cpp):
// every stored id is in range and every id is used; every tet's edge (face) id points at an
// entry equal to that tet's sorted vertex pair (triple); and the entries are strictly
// ascending. So the entries are exactly the distinct edges (faces) of the tets, in
// lexicographic order, which is the fresh build's numbering, and each tet's ids are the ones
// the fresh build would give. faceTets: each tet is listed by every face it names, every
// listed tet names the face, and each list is ascending (−1 last): exactly the fresh build's
// lists. Entries are written with relaxed atomic stores (plain moves, no read-modify-write)
// and checked after the pass, so damaged ids can only make a check fail, never race; the
// result is the same for any thread count.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>

#include "core/error.h"
#include "core/point_locator.h"
#include "core/tet_mesh.h"
#include "core/tet_mesh_local.h"

namespace tfd::core {
namespace {

using tet_local::kEdge;
using tet_local::kFace;

constexpr std::size_t kGrain = 8192;

TetMesh::Edge edgeOf(const TetMesh::Tet& tet, int k) {
  const int a = tet[kEdge[k][0]], b = tet[kEdge[k][1]];
  return a < b ? TetMesh::Edge{a, b} : TetMesh::Edge{b, a};
}

TetMesh::Face faceOf(const TetMesh::Tet& tet, int i) {
  int a = tet[kFace[i][0]], b = tet[kFace[i][1]], c = tet[kFace[i][2]];
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

template <std::size_t N>
void storeAtomic(std::array<int, N>& slot, const std::array<int, N>& value) {
  for (std::size_t i = 0; i < N; ++i)
    std::atomic_ref<int>(slot[i]).store(value[i], std::memory_order_relaxed);
}

template <std::size_t N>
bool same(const std::array<int, N>& a, const std::array<int, N>& b) {
  bool equal = true;
  for (std::size_t i = 0; i < N; ++i) equal &= a[i] == b[i];
  return equal;
}

/// Every entry written (first coordinate not −1) and strictly ascending.
template <class Entry>
bool writtenAndAscending(const std::vector<Entry>& entries) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, entries.size(), kGrain), true,
      [&](const auto& r, bool ok) {
        for (std::size_t e = r.begin(); ok && e != r.end(); ++e)
          ok = entries[e][0] >= 0 && (e == 0 || entries[e - 1] < entries[e]);
        return ok;
      },
      [](bool a, bool b) { return a && b; });
}

}  // namespace

TetMesh::TetMesh(std::vector<Vec3> positions, std::vector<Tet> tets, StoredTopology stored)
    : positions_(std::move(positions)),
      tets_(std::move(tets)),
      tetEdges_(std::move(stored.tetEdges)),
      faceTets_(std::move(stored.faceTets)),
      tetFaces_(std::move(stored.tetFaces)) {
  if (!quickCheckAndVolumes() || !buildIncidence(Progress())) throwInvalid();
  if (!restoreEdgesAndFaces())
    throw Error("stored mesh topology does not match its tets (" + std::to_string(tets_.size()) +
                " tets)");
  buildSummaries();
  buildBoundary();
}

bool TetMesh::restoreEdgesAndFaces() {
  const std::size_t nt = tets_.size();
  if (tetEdges_.size() != nt || tetFaces_.size() != nt) return false;
  // Id ranges: the counts are the largest ids + 1, bounded by what the tets can hold.
  struct Range {
    int minId = 0, maxEdge = -1, maxFace = -1;
  };
  const Range range = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, nt, kGrain), Range{},
      [&](const auto& r, Range acc) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          for (int e : tetEdges_[t]) {
            acc.minId = std::min(acc.minId, e);
            acc.maxEdge = std::max(acc.maxEdge, e);
          }
          for (int f : tetFaces_[t]) {
            acc.minId = std::min(acc.minId, f);
            acc.maxFace = std::max(acc.maxFace, f);
          }
        }
        return acc;
      },
      [](Range a, const Range& b) {
        a.minId = std::min(a.minId, b.minId);
        a.maxEdge = std::max(a.maxEdge, b.maxEdge);
        a.maxFace = std::max(a.maxFace, b.maxFace);
        return a;
      });
  if (range.minId < 0 || std::size_t(range.maxEdge) >= 6 * nt ||
      std::size_t(range.maxFace) >= 4 * nt || faceTets_.size() != std::size_t(range.maxFace) + 1)
    return false;
  edges_.assign(std::size_t(range.maxEdge) + 1, Edge{-1, -1});
  faces_.assign(faceTets_.size(), Face{-1, -1, -1});
  // Pass 1: each tet writes its edges and faces at their stored ids.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, kGrain), [&](const auto& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      for (int k = 0; k < 6; ++k) storeAtomic(edges_[tetEdges_[t][k]], edgeOf(tets_[t], k));
      for (int i = 0; i < 4; ++i) storeAtomic(faces_[tetFaces_[t][i]], faceOf(tets_[t], i));
    }
  });
  // Pass 2: every tet finds its own edges and faces there, and is listed by its faces.
  const auto all = [](bool a, bool b) { return a && b; };
  bool ok = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, nt, kGrain), true,
      [&](const auto& r, bool good) {
        for (std::size_t t = r.begin(); good && t != r.end(); ++t) {
          const Tet& tet = tets_[t];
          for (int k = 0; k < 6; ++k) good &= same(edges_[tetEdges_[t][k]], edgeOf(tet, k));
          for (int i = 0; i < 4; ++i) {
            const int f = tetFaces_[t][i];
            good &= same(faces_[f], faceOf(tet, i));
            good &= faceTets_[f][0] == int(t) || faceTets_[f][1] == int(t);
          }
        }
        return good;
      },
      all);
  if (!ok || !writtenAndAscending(edges_) || !writtenAndAscending(faces_)) return false;
  // Pass 3: each face lists one or two tets, ascending, each naming the face.
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, faces_.size(), kGrain), true,
      [&](const auto& r, bool good) {
        for (std::size_t f = r.begin(); good && f != r.end(); ++f) {
          const auto [a, b] = faceTets_[f];
          good = a >= 0 && std::size_t(a) < nt && (b == -1 || (b > a && std::size_t(b) < nt));
          const auto names = [&](int t) {
            const auto& ids = tetFaces_[t];
            return ids[0] == int(f) || ids[1] == int(f) || ids[2] == int(f) || ids[3] == int(f);
          };
          good = good && names(a) && (b == -1 || names(b));
        }
        return good;
      },
      all);
}

}  // namespace tfd::core
