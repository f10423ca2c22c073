#include "core/surface/surface_check.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <sstream>

namespace tfd::core {
namespace {

/// Spells out at most `max` problems of each kind and summarises the rest.
class Problems {
 public:
  explicit Problems(int max) : max_(max) {}
  template <class Fn>
  void add(const std::string& kind, Fn&& describe) {
    if (counts_[kind]++ < max_) list_.push_back(describe());
  }
  bool empty() const { return list_.empty(); }
  std::vector<std::string> finish() {
    for (const auto& [kind, count] : counts_) {
      if (count > max_) list_.push_back(std::to_string(count - max_) + " more: " + kind);
    }
    return std::move(list_);
  }

 private:
  int max_;
  std::vector<std::string> list_;
  std::map<std::string, int> counts_;
};

struct HalfEdge {
  int lo, hi;  // undirected key
  int tri;
  bool forward;  // runs lo -> hi
  bool operator<(const HalfEdge& o) const {
    if (lo != o.lo) return lo < o.lo;
    if (hi != o.hi) return hi < o.hi;
    return tri < o.tri;
  }
};

std::vector<HalfEdge> halfEdges(const SurfaceMesh& mesh) {
  std::vector<HalfEdge> h;
  h.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3];
      h.push_back({std::min(a, b), std::max(a, b), int(t), a < b});
    }
  }
  std::sort(h.begin(), h.end());
  return h;
}

std::string edgeName(int a, int b) {
  return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::string> closedSurfaceProblems(const SurfaceMesh& mesh, int maxReported) {
  if (mesh.triangles.empty()) return {"the surface has no triangles"};
  Problems problems(maxReported);
  const int n = int(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int v : tri) {
      if (v < 0 || v >= n) {
        problems.add("vertex index out of range", [&] {
          return "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                 ", out of range [0, " + std::to_string(n) + ")";
        });
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      problems.add("triangles repeating a vertex",
                   [&] { return "triangle " + std::to_string(t) + " repeats a vertex"; });
    }
  }
  if (!problems.empty()) return problems.finish();
  std::vector<unsigned char> used(n, 0);
  for (const auto& tri : mesh.triangles) {
    for (int v : tri) used[v] = 1;
  }
  for (int v = 0; v < n; ++v) {
    if (used[v] && !mesh.positions[v].allFinite()) {
      problems.add("non-finite coordinates",
                   [&] { return "vertex " + std::to_string(v) + " has a non-finite coordinate"; });
    }
  }

  const auto h = halfEdges(mesh);
  bool edgesOk = true;
  for (std::size_t i = 0; i < h.size();) {
    std::size_t j = i;
    while (j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi) ++j;
    const std::size_t count = j - i;
    if (count == 1) {
      edgesOk = false;
      problems.add("open edges", [&] {
        return edgeName(h[i].lo, h[i].hi) + " belongs to only one triangle (" +
               std::to_string(h[i].tri) + "): the surface is not closed";
      });
    } else if (count > 2) {
      edgesOk = false;
      problems.add("non-manifold edges", [&] {
        return edgeName(h[i].lo, h[i].hi) + " is shared by " + std::to_string(count) +
               " triangles (non-manifold)";
      });
    } else if (h[i].forward == h[i + 1].forward) {
      edgesOk = false;
      problems.add("inconsistently oriented edges", [&] {
        return "triangles " + std::to_string(h[i].tri) + " and " + std::to_string(h[i + 1].tri) +
               " run " + edgeName(h[i].lo, h[i].hi) +
               " in the same direction (inconsistent orientation)";
      });
    }
    i = j;
  }
  if (!edgesOk) return problems.finish();

  // Non-manifold vertices: the triangles around a vertex must form one fan.
  std::vector<int> start(n + 1, 0);
  for (const auto& tri : mesh.triangles) {
    for (int v : tri) ++start[v + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> around(start.back());
  {
    auto fill = start;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (int v : mesh.triangles[t]) around[fill[v]++] = int(t);
    }
  }
  std::vector<int> parent;
  std::map<int, int> firstByNeighbour;
  for (int v = 0; v < n; ++v) {
    const int k = start[v + 1] - start[v];
    if (k == 0) continue;
    parent.resize(k);
    std::iota(parent.begin(), parent.end(), 0);
    firstByNeighbour.clear();
    for (int i = 0; i < k; ++i) {
      for (int w : mesh.triangles[around[start[v] + i]]) {
        if (w == v) continue;
        auto [it, inserted] = firstByNeighbour.emplace(w, i);
        if (!inserted) parent[findRoot(parent, i)] = findRoot(parent, it->second);
      }
    }
    int fans = 0;
    for (int i = 0; i < k; ++i) fans += findRoot(parent, i) == i;
    if (fans > 1) {
      problems.add("non-manifold vertices", [&] {
        return "vertex " + std::to_string(v) + " joins " + std::to_string(fans) +
               " separate fans of triangles (non-manifold vertex)";
      });
    }
  }
  if (!problems.empty()) return problems.finish();

  const double volume = enclosedVolume(mesh);
  double lo = 0;
  Vec3 mn = Vec3::Constant(1e300), mx = Vec3::Constant(-1e300);
  for (int v = 0; v < n; ++v) {
    if (!used[v]) continue;
    mn = mn.cwiseMin(mesh.positions[v]);
    mx = mx.cwiseMax(mesh.positions[v]);
  }
  lo = (mx - mn).maxCoeff();
  if (!(std::abs(volume) > 1e-12 * lo * lo * lo)) {
    std::ostringstream s;
    s << "the surface encloses no volume: its signed volume, " << volume
      << ", is negligible for its size (" << lo
      << " across; flat, or a vertex far from the others?)";
    problems.add("zero volume", [&] { return s.str(); });
  }
  return problems.finish();
}

double enclosedVolume(const SurfaceMesh& mesh) {
  double sum = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3& b = mesh.positions[t[1]];
    const Vec3& c = mesh.positions[t[2]];
    sum += a.dot(b.cross(c));
  }
  return sum / 6.0;
}

double surfaceArea(const SurfaceMesh& mesh) {
  double sum = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    sum += (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm() / 2;
  }
  return sum;
}

double meanEdgeLength(const SurfaceMesh& mesh) {
  const auto h = halfEdges(mesh);
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (i > 0 && h[i].lo == h[i - 1].lo && h[i].hi == h[i - 1].hi) continue;
    sum += (mesh.positions[h[i].lo] - mesh.positions[h[i].hi]).norm();
    ++count;
  }
  return count ? sum / double(count) : 0.0;
}

double medianEdgeLength(const SurfaceMesh& mesh) {
  std::vector<double> lengths;
  lengths.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      lengths.push_back((mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
  if (lengths.empty()) return 0;
  const auto middle = lengths.begin() + (lengths.size() - 1) / 2;
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

long eulerCharacteristic(const SurfaceMesh& mesh) {
  const auto h = halfEdges(mesh);
  long edges = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (i == 0 || h[i].lo != h[i - 1].lo || h[i].hi != h[i - 1].hi) ++edges;
  }
  std::vector<unsigned char> used(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles) {
    for (int v : t) used[v] = 1;
  }
  const long vertices = std::count(used.begin(), used.end(), 1);
  return vertices - edges + long(mesh.triangles.size());
}

void removeUnreferencedVertices(SurfaceMesh& mesh) {
  std::vector<int> map(mesh.positions.size(), -1);
  for (const auto& t : mesh.triangles) {
    for (int v : t) map[v] = 0;
  }
  int next = 0;
  for (std::size_t v = 0; v < map.size(); ++v) {
    if (map[v] == 0) {
      mesh.positions[next] = mesh.positions[v];
      map[v] = next++;
    }
  }
  mesh.positions.resize(next);
  for (auto& t : mesh.triangles) {
    for (int& v : t) v = map[v];
  }
}

void flipOrientation(SurfaceMesh& mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

std::vector<int> vertexPieces(const SurfaceMesh& s) {
  std::vector<int> parent(s.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : s.triangles) {
    parent[findRoot(parent, t[1])] = findRoot(parent, t[0]);
    parent[findRoot(parent, t[2])] = findRoot(parent, t[0]);
  }
  std::vector<int> piece(s.positions.size(), -1), pieceOfRoot(s.positions.size(), -1);
  int pieces = 0;
  for (const auto& t : s.triangles) {
    int& p = pieceOfRoot[findRoot(parent, t[0])];
    if (p < 0) p = pieces++;
    for (int v : t) piece[v] = p;
  }
  return piece;
}

int connectedComponents(const SurfaceMesh& s) {
  const std::vector<int> piece = vertexPieces(s);
  return piece.empty() ? 0 : *std::max_element(piece.begin(), piece.end()) + 1;
}

}  // namespace tfd::core
