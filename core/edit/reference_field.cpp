#include "core/edit/reference_field.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <string>

#include "core/design/parallel_transport.h"
#include "core/error.h"

namespace tfd::core {
namespace {

/// Position in TetMesh::tetEdges order (01, 02, 03, 12, 13, 23) of the edge joining local
/// tet corners i and j.
constexpr int kEdgeOf[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

/// A region tet's local corners and edges (tetEdges order), looked up when the tet joins.
struct RegionTet {
  std::array<int, 4> v;
  std::array<int, 6> e;
};

class Propagation {
 public:
  Propagation(const TetMesh& mesh, const RegionComplex& region, const std::vector<Vec3>& n)
      : mesh_(mesh), region_(region), n_(n) {
    const int tets = static_cast<int>(region.tets.size());
    // The local face neighbours of every tet, which each candidate test reads (16 bytes a tet;
    // corners and edges are looked up once, when a tet joins). Each entry depends only on its
    // tet: filled in parallel (the same for any thread count), not zeroed first.
    nb_.reset(new std::array<int, 4>[tets]);
    tbb::parallel_for(tbb::blocked_range<int>(0, tets, 1024),
                      [&](const tbb::blocked_range<int>& b) {
                        for (int lt = b.begin(); lt != b.end(); ++lt) {
                          const int t = region.tets[lt];
                          for (int i = 0; i < 4; ++i) {
                            const auto& ft = mesh.faceTets()[mesh.tetFaces()[t][i]];
                            const int other = ft[0] == t ? ft[1] : ft[0];
                            nb_[lt][i] = other < 0 ? -1 : region.localTet(other);
                          }
                        }
                      });
    visited_.assign(tets, 0);
    shared_.assign(tets, 0);
    hasU_.assign(region.vertices.size(), 0);
    known_.assign(region.edges.size(), 0);
    out_.reference.assign(region.vertices.size(), Vec3::Zero());
    out_.jumps.assign(region.edges.size(), 0.0);
  }

  ReferenceField run(int seed, const Vec3& seedReference, bool measureHolonomy) {
    out_.seedVertex = region_.vertices[seed];
    out_.reference[seed] = initialReference(n_[seed], seedReference);
    hasU_[seed] = 1;
    int seedTet = -1;
    for (int t : mesh_.vertexTets(region_.vertices[seed])) {
      if ((seedTet = region_.localTet(t)) >= 0) break;
    }
    add(seedTet);
    std::size_t count = 1;
    std::vector<int> deferred;
    while (count < region_.tets.size()) {
      for (int t; (t = next()) >= 0;) {
        if (visited_[t]) continue;
        if (simple(t)) {
          add(t);
          ++count;
        } else {
          deferred.push_back(t);
        }
      }
      if (count == region_.tets.size()) break;
      // No tet keeps the set a ball: take the one sharing most faces (lowest index on ties).
      int best = -1, bestShared = 0;
      std::erase_if(deferred, [&](int t) { return visited_[t] != 0; });
      for (int t : deferred) {
        const int s = shared(t);
        if (s > bestShared || (s == bestShared && s > 0 && t < best)) best = t, bestShared = s;
      }
      if (best < 0) {
        throw Error("reference field: the region is not connected through faces (" +
                    std::to_string(region_.tets.size() - count) + " of " +
                    std::to_string(region_.tets.size()) + " tets unreachable)");
      }
      ++out_.nonBallSteps;
      add(best);
      ++count;
    }
    if (measureHolonomy) out_.maxHolonomyDefect = maxHolonomyDefect();
    return std::move(out_);
  }

 private:
  static Vec3 initialReference(const Vec3& n, const Vec3& wanted) {
    Vec3 u = wanted - wanted.dot(n) * n;
    if (!(u.norm() > 1e-6 * std::max(1.0, wanted.norm()))) {
      int axis = 0;
      n.cwiseAbs().minCoeff(&axis);
      const Vec3 e = Vec3::Unit(axis);
      u = e - e.dot(n) * n;
    }
    return u.normalized();
  }

  int next() {
    for (int b = 2; b >= 0; --b) {
      if (!queue_[b].empty()) {
        const int t = queue_[b].front();
        queue_[b].pop_front();
        return t;
      }
    }
    return -1;
  }

  /// Number of the tet's faces shared with visited tets.
  int shared(int t) const { return shared_[t]; }

  /// Whether adding t keeps the visited set a ball: its contact with the set is a disk.
  bool simple(int t) const {
    const std::array<int, 4>& nb = nb_[t];
    int faces[4], s = 0;
    for (int i = 0; i < 4; ++i)
      if (nb[i] >= 0 && visited_[nb[i]]) faces[s++] = i;
    const int meshTet = region_.tets[t];
    if (s == 1)  // the opposite corner must be new
      return !hasU_[region_.localVertex(mesh_.tets()[meshTet][faces[0]])];
    if (s == 2)  // and the edge between them
      return !known_[region_.localEdge(mesh_.tetEdges()[meshTet][kEdgeOf[faces[0]][faces[1]]])];
    return s == 3;
  }

  /// Local tet t's corners and edges, from the mesh and the region's lookup tables.
  RegionTet corners(int t) const {
    const int meshTet = region_.tets[t];
    RegionTet r;
    for (int i = 0; i < 4; ++i) r.v[i] = region_.localVertex(mesh_.tets()[meshTet][i]);
    for (int k = 0; k < 6; ++k) r.e[k] = region_.localEdge(mesh_.tetEdges()[meshTet][k]);
    return r;
  }

  /// Worst defect over the four triangles of every tet. A jump is final once set, so this is
  /// the same whenever it is computed: after the (sequential) propagation, in parallel; the
  /// maximum does not depend on the order.
  double maxHolonomyDefect() const {
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, static_cast<int>(region_.tets.size()), 1024), 0.0,
        [&](const tbb::blocked_range<int>& b, double worst) {
          for (int t = b.begin(); t != b.end(); ++t) {
            const RegionTet r = corners(t);
            for (int skip = 0; skip < 4; ++skip) {  // the four triangles
              int c[3], k = 0;
              for (int i = 0; i < 4; ++i)
                if (i != skip) c[k++] = i;
              const int a = r.v[c[0]], bv = r.v[c[1]], m = r.v[c[2]];
              const double defect = jump(r.e[kEdgeOf[c[0]][c[1]]], a, bv) +
                                    jump(r.e[kEdgeOf[c[1]][c[2]]], bv, m) +
                                    jump(r.e[kEdgeOf[c[2]][c[0]]], m, a) -
                                    sphericalTriangleArea(n_[a], n_[bv], n_[m]);
              worst = std::max(worst, std::abs(defect));
            }
          }
          return worst;
        },
        [](double x, double y) { return std::max(x, y); });
  }

  double jump(int e, int from, int to) const { return orientedJump(out_.jumps[e], from, to); }
  void setJump(int e, int from, int to, double g) {
    out_.jumps[e] = from < to ? g : -g;
    known_[e] = 1;
  }

  Mat3 transport(int a, int b) const {
    try {
      return transportRotation(n_[a], n_[b]);
    } catch (const Error&) {
      throw Error("reference field: the directions at vertices " +
                  std::to_string(region_.vertices[a]) + " and " +
                  std::to_string(region_.vertices[b]) +
                  " are opposite (the eigenvector is not vectorised)");
    }
  }

  void add(int t) {
    visited_[t] = 1;
    const RegionTet r = corners(t);
    // A new corner takes U transported from the best-aligned corner that has one (jump 0).
    for (int i = 0; i < 4; ++i) {
      if (hasU_[r.v[i]]) continue;
      int from = -1;
      for (int j = 0; j < 4; ++j) {
        if (j == i || !hasU_[r.v[j]]) continue;
        if (from < 0 || n_[r.v[j]].dot(n_[r.v[i]]) > n_[r.v[from]].dot(n_[r.v[i]])) from = j;
      }
      const int a = r.v[from], b = r.v[i];
      Vec3 u = transport(a, b) * out_.reference[a];
      out_.reference[b] = (u - u.dot(n_[b]) * n_[b]).normalized();
      hasU_[b] = 1;
      setJump(r.e[kEdgeOf[from][i]], a, b, 0.0);
    }
    // Every other new edge from a triangle of t whose two other edges are known.
    for (bool progress = true; progress;) {
      progress = false;
      int unknown = -1;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          if (known_[r.e[kEdgeOf[i][j]]]) continue;
          unknown = kEdgeOf[i][j];
          for (int c = 0; c < 4 && !known_[r.e[kEdgeOf[i][j]]]; ++c) {
            if (c == i || c == j || !known_[r.e[kEdgeOf[j][c]]] || !known_[r.e[kEdgeOf[c][i]]])
              continue;
            const int a = r.v[i], b = r.v[j], m = r.v[c];
            const double g = sphericalTriangleArea(n_[a], n_[b], n_[m]) -
                             jump(r.e[kEdgeOf[j][c]], b, m) - jump(r.e[kEdgeOf[c][i]], m, a);
            setJump(r.e[kEdgeOf[i][j]], a, b, g);
            progress = true;
          }
        }
      if (!progress && unknown >= 0) {
        // Only after a non-ball step: the wrapped angle of transport along the edge.
        int i = 0, j = 1;
        for (int p = 0; p < 4; ++p)
          for (int q = p + 1; q < 4; ++q)
            if (kEdgeOf[p][q] == unknown) i = p, j = q;
        const int a = r.v[i], b = r.v[j];
        const Vec3 moved = transport(a, b) * out_.reference[a];
        setJump(r.e[unknown], a, b, signedAngle(out_.reference[b], moved, n_[b]));
        progress = true;
      }
    }
    for (int nb : nb_[t]) {
      if (nb < 0) continue;
      ++shared_[nb];  // face adjacency is symmetric: t is one of nb's neighbours
      if (!visited_[nb]) queue_[std::min(shared(nb), 3) - 1].push_back(nb);
    }
  }

  const TetMesh& mesh_;
  const RegionComplex& region_;
  const std::vector<Vec3>& n_;
  std::unique_ptr<std::array<int, 4>[]> nb_;
  std::vector<char> visited_, hasU_, known_;
  /// Per tet, its faces shared with visited tets (kept as tets join, instead of reading the
  /// four neighbours' flags: a random access each).
  std::vector<unsigned char> shared_;
  /// Candidates by the number of faces they share with the visited set (when queued): those
  /// sharing most are taken first, which keeps the front compact (fewer tets that could only
  /// join by breaking the ball). Entries may be stale; simple() decides on the current state.
  std::deque<int> queue_[3];
  ReferenceField out_;
};

}  // namespace

double sphericalTriangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 2 * std::atan2(a.dot(b.cross(c)), 1 + a.dot(b) + b.dot(c) + c.dot(a));
}

ReferenceField referenceField(const TetMesh& mesh, const RegionComplex& region,
                              const std::vector<Vec3>& directions, int seed,
                              const Vec3& seedReference, bool measureHolonomy) {
  if (directions.size() != region.vertices.size()) {
    throw Error("reference field: one direction per region vertex expected");
  }
  if (seed < 0 || seed >= static_cast<int>(region.vertices.size())) {
    throw Error("reference field: the seed is not a region vertex");
  }
  return Propagation(mesh, region, directions).run(seed, seedReference, measureHolonomy);
}

}  // namespace tfd::core
