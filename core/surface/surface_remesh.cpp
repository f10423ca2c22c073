#include "core/surface/surface_remesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace tfd::core {
namespace {

using Tri = std::array<int, 3>;

/// Triangle soup with vertex-to-triangle incidence, edited in place. Dead triangles have
/// t[0] = -1; dead vertices have no triangles.
class EditableMesh {
 public:
  explicit EditableMesh(SurfaceMesh&& mesh)
      : pos_(std::move(mesh.positions)), tri_(std::move(mesh.triangles)), vt_(pos_.size()) {
    for (int t = 0; t < int(tri_.size()); ++t) {
      for (int v : tri_[t]) vt_[v].push_back(t);
    }
  }

  SurfaceMesh release() {
    SurfaceMesh out;
    std::vector<int> map(pos_.size(), -1);
    for (int v = 0; v < int(pos_.size()); ++v) {
      if (!vt_[v].empty()) {
        map[v] = int(out.positions.size());
        out.positions.push_back(pos_[v]);
      }
    }
    for (const auto& t : tri_) {
      if (t[0] >= 0) out.triangles.push_back({map[t[0]], map[t[1]], map[t[2]]});
    }
    return out;
  }

  /// Unique edges (a < b) of live triangles, sorted.
  std::vector<std::array<int, 2>> edges() const {
    std::vector<std::array<int, 2>> e;
    for (const auto& t : tri_) {
      if (t[0] < 0) continue;
      for (int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        if (a < b) e.push_back({a, b});
      }
    }
    std::sort(e.begin(), e.end());
    return e;
  }

  double length(int a, int b) const { return (pos_[a] - pos_[b]).norm(); }

  /// Finds the triangles (a, b, c) and (b, a, d) of edge ab; false when ab is not an edge.
  bool wings(int a, int b, int& t1, int& c, int& t2, int& d) const {
    t1 = t2 = -1;
    for (int t : vt_[a]) {
      const auto& tr = tri_[t];
      for (int i = 0; i < 3; ++i) {
        if (tr[i] == a && tr[(i + 1) % 3] == b) {
          t1 = t;
          c = tr[(i + 2) % 3];
        } else if (tr[i] == b && tr[(i + 1) % 3] == a) {
          t2 = t;
          d = tr[(i + 2) % 3];
        }
      }
    }
    return t1 >= 0 && t2 >= 0;
  }

  /// Sorted neighbours of v, into `n` (reused buffers avoid allocations in the hot loops).
  void neighbours(int v, std::vector<int>& n) const {
    n.clear();
    for (int t : vt_[v]) {
      for (int w : tri_[t]) {
        if (w != v) n.push_back(w);
      }
    }
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }

  int valence(int v) const { return int(vt_[v].size()); }  // closed manifold: #edges = #tris

  Vec3 normal(const Tri& t) const {
    return (pos_[t[1]] - pos_[t[0]]).cross(pos_[t[2]] - pos_[t[0]]);
  }

  Vec3 vertexNormal(int v) const {
    Vec3 n = Vec3::Zero();
    for (int t : vt_[v]) n += normal(tri_[t]);
    return n;
  }

  void split(int a, int b, const Vec3& x) {
    int t1, c = -1, t2, d = -1;
    if (!wings(a, b, t1, c, t2, d)) return;
    const int m = int(pos_.size());
    pos_.push_back(x);
    vt_.emplace_back();
    const int t3 = int(tri_.size()), t4 = t3 + 1;
    tri_[t1] = {a, m, c};
    tri_.push_back({m, b, c});
    tri_[t2] = {b, m, d};
    tri_.push_back({m, a, d});
    erase(b, t1);
    vt_[b].push_back(t3);
    erase(a, t2);
    vt_[a].push_back(t4);
    vt_[c].push_back(t3);
    vt_[d].push_back(t4);
    vt_[m] = {t1, t3, t2, t4};
  }

  /// Collapses b into a, which moves to the projected edge midpoint x, when that keeps the surface
  /// a manifold of the same topology without folded or over-long edges. Returns whether it did.
  bool tryCollapse(int a, int b, const SurfaceProjection& project, double maxLength) {
    int t1, c = -1, t2, d = -1;
    if (!wings(a, b, t1, c, t2, d)) return false;
    if (valence(c) <= 3 || valence(d) <= 3 || valence(a) + valence(b) - 4 < 3) return false;
    auto& na = scratchA_;
    auto& nb = scratchB_;
    neighbours(a, na);
    neighbours(b, nb);
    std::size_t common = 0;  // link condition: a and b share exactly c and d
    for (std::size_t i = 0, j = 0; i < na.size() && j < nb.size();) {
      if (na[i] < nb[j]) {
        ++i;
      } else if (nb[j] < na[i]) {
        ++j;
      } else {
        ++common, ++i, ++j;
      }
    }
    if (common != 2) return false;
    const Vec3 x = project((pos_[a] + pos_[b]) / 2);
    for (int w : na) {
      if (w != b && (pos_[w] - x).norm() > maxLength) return false;
    }
    for (int w : nb) {
      if (w != a && (pos_[w] - x).norm() > maxLength) return false;
    }
    for (int v : {a, b}) {
      const Vec3 around = vertexNormal(v);
      for (int t : vt_[v]) {
        if (t == t1 || t == t2) continue;
        Tri moved = tri_[t];
        const Vec3 before = normal(moved);
        Vec3 p[3];
        for (int i = 0; i < 3; ++i) p[i] = (moved[i] == a || moved[i] == b) ? x : pos_[moved[i]];
        const Vec3 after = (p[1] - p[0]).cross(p[2] - p[0]);
        const double an = after.norm(), bn = before.norm();
        if (!(an > 1e-12 * maxLength * maxLength)) return false;
        if (bn > 1e-9 * maxLength * maxLength) {
          if (after.dot(before) < 0.3 * an * bn) return false;
        } else if (after.dot(around) <= 0) {
          return false;
        }
      }
    }
    // Apply.
    tri_[t1][0] = -1;
    tri_[t2][0] = -1;
    erase(a, t1);
    erase(a, t2);
    erase(c, t1);
    erase(d, t2);
    for (int t : vt_[b]) {
      if (t == t1 || t == t2) continue;
      for (int& v : tri_[t]) {
        if (v == b) v = a;
      }
      vt_[a].push_back(t);
    }
    vt_[b].clear();
    pos_[a] = x;
    return true;
  }

  /// Flips edge ab when that lowers the valence excess and the two triangles are nearly flat.
  bool tryFlip(int a, int b) {
    int t1, c = -1, t2, d = -1;
    if (!wings(a, b, t1, c, t2, d)) return false;
    if (c == d || valence(a) <= 3 || valence(b) <= 3) return false;
    auto dev = [](int v) { return std::abs(v - 6); };
    const int before = dev(valence(a)) + dev(valence(b)) + dev(valence(c)) + dev(valence(d));
    const int after =
        dev(valence(a) - 1) + dev(valence(b) - 1) + dev(valence(c) + 1) + dev(valence(d) + 1);
    if (after >= before) return false;
    auto& nc = scratchA_;
    neighbours(c, nc);
    if (std::binary_search(nc.begin(), nc.end(), d)) return false;
    const Vec3 n1 = normal(tri_[t1]), n2 = normal(tri_[t2]);
    if (n1.dot(n2) < 0.85 * n1.norm() * n2.norm()) return false;
    const Tri u1 = {a, d, c}, u2 = {d, b, c};
    const Vec3 m1 = normal(u1), m2 = normal(u2), sum = n1 + n2;
    if (m1.dot(sum) <= 0.5 * m1.norm() * sum.norm() || m2.dot(sum) <= 0.5 * m2.norm() * sum.norm())
      return false;
    tri_[t1] = u1;
    tri_[t2] = u2;
    erase(a, t2);
    erase(b, t1);
    vt_[c].push_back(t2);
    vt_[d].push_back(t1);
    return true;
  }

  void smooth(const SurfaceProjection& project) {
    std::vector<Vec3> next(pos_.size());
    for (int v = 0; v < int(pos_.size()); ++v) {
      if (vt_[v].empty()) continue;
      auto& nb = scratchA_;
      neighbours(v, nb);
      Vec3 centroid = Vec3::Zero();
      for (int w : nb) centroid += pos_[w];
      centroid /= double(nb.size());
      Vec3 n = vertexNormal(v);
      const double len = n.norm();
      Vec3 move = centroid - pos_[v];
      if (len > 0) {
        n /= len;
        move -= n.dot(move) * n;
      }
      next[v] = project(pos_[v] + 0.5 * move);
    }
    for (int v = 0; v < int(pos_.size()); ++v) {
      if (!vt_[v].empty()) pos_[v] = next[v];
    }
  }

  const Vec3& position(int v) const { return pos_[v]; }
  bool alive(int v) const { return !vt_[v].empty(); }

 private:
  void erase(int v, int t) {
    auto& list = vt_[v];
    list.erase(std::find(list.begin(), list.end(), t));
  }

  std::vector<Vec3> pos_;
  std::vector<Tri> tri_;
  std::vector<std::vector<int>> vt_;
  std::vector<int> scratchA_, scratchB_;
};

}  // namespace

void remeshIsotropic(SurfaceMesh& mesh, double edgeLength, const SurfaceProjection& project,
                     int iterations) {
  if (!(edgeLength > 0)) throw Error("remeshIsotropic: edge length must be positive");
  const double high = 4.0 / 3.0 * edgeLength, low = 4.0 / 5.0 * edgeLength;
  EditableMesh m(std::move(mesh));
  for (int it = 0; it < iterations; ++it) {
    // Split until no edge is too long (each round at least halves the longest edges).
    for (int round = 0; round < 20; ++round) {
      bool any = false;
      for (const auto& [a, b] : m.edges()) {
        if (m.length(a, b) > high) {
          m.split(a, b, project((m.position(a) + m.position(b)) / 2));
          any = true;
        }
      }
      if (!any) break;
    }
    // Collapse short edges, shortest first.
    for (int round = 0; round < 10; ++round) {
      auto e = m.edges();
      std::vector<std::pair<double, std::array<int, 2>>> shorts;
      for (const auto& ab : e) {
        const double l = m.length(ab[0], ab[1]);
        if (l < low) shorts.push_back({l, ab});
      }
      std::sort(shorts.begin(), shorts.end());
      int done = 0;
      for (const auto& [l, ab] : shorts) {
        const auto [a, b] = ab;
        if (!m.alive(a) || !m.alive(b) || m.length(a, b) >= low) continue;
        done += m.tryCollapse(a, b, project, high);
      }
      if (done * 100 <= int(shorts.size())) break;  // what is left is locked in place
    }
    for (const auto& [a, b] : m.edges()) m.tryFlip(a, b);
    m.smooth(project);
  }
  mesh = m.release();
}

}  // namespace tfd::core
