#include "core/edit/reconnect_sheet.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>

#include "core/edit/reconnect_segments.h"
#include "core/region/curve_tube.h"

namespace tfd::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<int> localVertices(const RegionComplex& region, const std::vector<int>& meshIds) {
  std::vector<int> out;
  for (int v : meshIds)
    if (const int l = region.localVertex(v); l >= 0) out.push_back(l);
  return out;
}

/// Shortest path (local vertices) from one end to the other through the region's edges,
/// avoiding `blocked` local vertices except the ends' own; empty when there is none.
std::vector<int> shortestPath(const TetMesh& mesh, const RegionComplex& region,
                              const SheetEnd& from, const SheetEnd& to,
                              const std::vector<char>& blocked, double& length) {
  const auto& P = mesh.positions();
  const std::size_t n = region.vertices.size();
  std::vector<double> dist(n, kInf);
  std::vector<int> prev(n, -1);
  std::vector<char> goal(n, 0), start(n, 0);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int l : localVertices(region, sourceVertices(mesh, from.source))) {
    start[l] = 1;
    dist[l] = (P[region.vertices[l]] - from.position).norm();
    queue.emplace(dist[l], l);
  }
  for (int l : localVertices(region, sourceVertices(mesh, to.source))) goal[l] = 1;
  double best = kInf;
  int bestVertex = -1;
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > dist[u] || d >= best) continue;
    if (goal[u]) {
      const double total = d + (P[region.vertices[u]] - to.position).norm();
      if (total < best) best = total, bestVertex = u;
    }
    for (int k = region.start[u]; k < region.start[u + 1]; ++k) {
      const int w = region.neighbour[k];
      if (blocked[w] && !goal[w] && !start[w]) continue;
      const double nd = d + (P[region.vertices[w]] - P[region.vertices[u]]).norm();
      if (nd < dist[w]) dist[w] = nd, prev[w] = u, queue.emplace(nd, w);
    }
  }
  std::size_t count = 0;
  for (int u = bestVertex; u >= 0; u = prev[u]) ++count;
  std::vector<int> path(count);
  for (int u = bestVertex; u >= 0; u = prev[u]) path[--count] = u;
  length = best;
  return path;
}

/// Nearest path of every local vertex by graph distance (ties: path 0).
std::vector<signed char> graphLabels(const TetMesh& mesh, const RegionComplex& region,
                                     const std::array<std::vector<int>, 2>& localPaths) {
  const auto& P = mesh.positions();
  const std::size_t n = region.vertices.size();
  std::vector<double> dist(n, kInf);
  std::vector<signed char> label(n, -1);
  using Item = std::tuple<double, int, int>;  // distance, label, vertex
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int k = 0; k < 2; ++k)
    for (int l : localPaths[k])
      if (dist[l] > 0) dist[l] = 0, queue.emplace(0.0, k, l);
  while (!queue.empty()) {
    const auto [d, k, u] = queue.top();
    queue.pop();
    if (label[u] >= 0) continue;
    label[u] = static_cast<signed char>(k);
    for (int e = region.start[u]; e < region.start[u + 1]; ++e) {
      const int w = region.neighbour[e];
      if (label[w] >= 0) continue;
      const double nd = d + (P[region.vertices[w]] - P[region.vertices[u]]).norm();
      if (nd <= dist[w]) dist[w] = nd, queue.emplace(nd, k, w);
    }
  }
  return label;
}

}  // namespace

ReconnectSheet reconnectSheet(const TetMesh& mesh, const RegionComplex& region,
                              const std::array<std::array<SheetEnd, 2>, 2>& pairs) {
  ReconnectSheet s;
  const std::size_t n = region.vertices.size();
  std::array<std::vector<int>, 2> local;
  std::vector<char> blocked(n, 0);
  for (int k = 0; k < 2; ++k) {
    local[k] = shortestPath(mesh, region, pairs[k][0], pairs[k][1], blocked, s.pathLengths[k]);
    if (local[k].empty()) {
      s.problem = k == 0 ? "no path in the region joins the ends of the first pair"
                         : "no path in the region joins the ends of the second pair without "
                           "meeting the first pair's path (the paths would intersect)";
      return s;
    }
    if (k == 1) break;
    for (int l : local[0]) {
      blocked[l] = 1;
      for (int e = region.start[l]; e < region.start[l + 1]; ++e) blocked[region.neighbour[e]] = 1;
    }
  }
  // The second path above already avoided the first; measure what the unconstrained one would
  // have touched (the paper's intersecting paths), for the report.
  double plainLength = 0;
  const std::vector<int> plain =
      shortestPath(mesh, region, pairs[1][0], pairs[1][1], std::vector<char>(n, 0), plainLength);
  for (int l : plain) s.contacts += blocked[l] != 0;
  if (s.contacts == 0) {
    local[1] = plain, s.pathLengths[1] = plainLength;
  } else {
    s.adjusted = true;
  }
  for (int l : local[1])
    if (std::find(local[0].begin(), local[0].end(), l) != local[0].end()) {
      s.problem = "the two paths meet at an end (the pairs' ends are too close)";
      return s;
    }
  for (int k = 0; k < 2; ++k)
    for (int l : local[k]) s.paths[k].push_back(region.vertices[l]);
  s.label = graphLabels(mesh, region, local);
  for (std::size_t t = 0; t < region.tets.size(); ++t) {
    const auto& tet = mesh.tets()[region.tets[t]];
    const signed char first = s.label[region.localVertex(tet[0])];
    for (int i = 1; i < 4; ++i)
      if (s.label[region.localVertex(tet[i])] != first) {
        s.tets.push_back(region.tets[t]);
        break;
      }
  }
  if (s.tets.empty()) s.problem = "the nearest-path partition left no sheet";
  return s;
}

std::vector<signed char> euclideanLabels(const TetMesh& mesh, const RegionComplex& region,
                                         const std::array<std::vector<int>, 2>& paths) {
  const auto& P = mesh.positions();
  std::vector<signed char> label(region.vertices.size(), 0);
  for (std::size_t i = 0; i < region.vertices.size(); ++i) {
    const Vec3& p = P[region.vertices[i]];
    double d[2] = {kInf, kInf};
    for (int k = 0; k < 2; ++k) {
      const auto& path = paths[k];
      if (path.size() == 1) d[k] = (p - P[path[0]]).norm();
      for (std::size_t j = 0; j + 1 < path.size(); ++j) {
        const Vec3 &a = P[path[j]], &b = P[path[j + 1]];
        const double t = closestSegmentParameter(p, a, b);
        d[k] = std::min(d[k], (p - ((1 - t) * a + t * b)).norm());
      }
    }
    label[i] = d[1] < d[0] ? 1 : 0;
  }
  return label;
}

}  // namespace tfd::core
