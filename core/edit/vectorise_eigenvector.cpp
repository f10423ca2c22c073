#include "core/edit/vectorise_eigenvector.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <tuple>

#include "core/edit/region_complex.h"
#include "core/error.h"
#include "core/region/bucket_queue.h"

namespace tfd::core {
namespace {

/// How isolated the non-repeating eigenvalue is, relative to ‖A‖ (0 at a degenerate point).
double isolation(const EigenDecomposition& d, DegenerateType type, double norm) {
  if (norm == 0) return 0;
  const Vec3& l = d.values;
  return (type == DegenerateType::Linear ? l[0] - l[1] : l[1] - l[2]) / norm;
}

/// The region's vertices oriented along a maximum spanning tree of |e_u·e_v| from `seed`;
/// the region must be connected.
void orientAlongTree(const RegionComplex& region, int seed, std::vector<Vec3>& dirs) {
  const int n = static_cast<int>(region.vertices.size());
  std::vector<char> done(n, 0);
  // (weight, −vertex, parent): the largest weight first, then the smallest vertex id (the
  // order of std::priority_queue<Entry>). Bucketed by 1 − weight, which does not decrease
  // along that order: most weights are close to 1 in a smooth field.
  using Entry = std::tuple<double, int, int>;
  OrderedBucketQueue<Entry, std::less<>> queue;
  const auto push = [&](int from) {
    for (int k = region.start[from]; k < region.start[from + 1]; ++k) {
      const int to = region.neighbour[k];
      if (done[to]) continue;
      const double weight = std::abs(dirs[from].dot(dirs[to]));
      queue.emplace(logBucket(1 - weight), Entry(weight, -to, from));
    }
  };
  done[seed] = 1;
  push(seed);
  while (!queue.empty()) {
    const auto [weight, negTo, from] = queue.top();
    queue.pop();
    const int to = -negTo;
    if (done[to]) continue;
    done[to] = 1;
    if (dirs[from].dot(dirs[to]) < 0) dirs[to] = -dirs[to];
    push(to);
  }
}

/// The orientation in which every region edge joins directions with a positive dot product,
/// found by a breadth-first traversal from `seed` (whose sign is kept); nullopt when the
/// traversal's signs leave some edge at a dot ≤ 0 (a sign conflict, or an edge of
/// perpendicular directions). Such an orientation is the only one in which no edge disagrees:
/// along any path each sign follows from the previous one through a non-zero dot. So it is
/// also the orientation of the spanning tree of orientAlongTree(), which only the
/// inconsistent case needs. Throws when the region is not connected.
std::optional<std::vector<char>> consistentFlips(const RegionComplex& region, int seed,
                                                 const std::vector<Vec3>& dirs) {
  const int n = static_cast<int>(region.vertices.size());
  std::vector<char> reached(n, 0), flip(n, 0);
  std::vector<int> queue;
  queue.reserve(n);
  queue.push_back(seed);
  reached[seed] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int from = queue[head];
    for (int k = region.start[from]; k < region.start[from + 1]; ++k) {
      const int to = region.neighbour[k];
      if (reached[to]) continue;
      reached[to] = 1;
      flip[to] = flip[from] ^ (dirs[from].dot(dirs[to]) < 0);
      queue.push_back(to);
    }
  }
  if (static_cast<int>(queue.size()) != n) {
    throw Error("vectorise eigenvector: the region is not connected (" +
                std::to_string(region.components()) + " pieces)");
  }
  const bool consistent = tbb::parallel_reduce(
      tbb::blocked_range<int>(0, n, 2048), true,
      [&](const tbb::blocked_range<int>& r, bool ok) {
        for (int i = r.begin(); i != r.end() && ok; ++i)
          for (int k = region.start[i]; k < region.start[i + 1] && ok; ++k) {
            const int j = region.neighbour[k];
            const double dot = dirs[i].dot(dirs[j]);
            ok = j < i || (flip[i] == flip[j] ? dot > 0 : dot < 0);
          }
        return ok;
      },
      [](bool a, bool b) { return a && b; });
  if (!consistent) return std::nullopt;
  return flip;
}

}  // namespace

int nonRepeatingColumn(DegenerateType type) { return type == DegenerateType::Linear ? 0 : 2; }

VectorisedEigenvector vectoriseEigenvector(const TensorField& field,
                                           const std::vector<int>& regionTets,
                                           DegenerateType type) {
  return vectoriseEigenvector(field, regionComplex(field.mesh(), regionTets), type);
}

VectorisedEigenvector vectoriseEigenvector(const TensorField& field, const RegionComplex& region,
                                           DegenerateType type) {
  const int n = static_cast<int>(region.vertices.size());
  const int column = nonRepeatingColumn(type);
  std::vector<Vec3> dirs(n);
  std::vector<double> gap(n);
  std::vector<ValuesAndMedium> eigen(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 256), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) {
      const Tensor a = field.at(region.vertices[i]).deviator();
      const EigenDecomposition d = eigenDecompose(a);
      eigen[i] = ValuesAndMedium::of(d);
      dirs[i] = d.vectors.col(column).normalized();
      gap[i] = isolation(d, type, a.norm());
    }
  });
  int seed = 0;
  for (int i = 1; i < n; ++i)
    if (gap[i] > gap[seed]) seed = i;
  int axis = 0;
  dirs[seed].cwiseAbs().maxCoeff(&axis);
  if (dirs[seed][axis] < 0) dirs[seed] = -dirs[seed];
  VectorisedEigenvector out;
  out.seed = region.vertices[seed];
  out.vertices = region.vertices;
  out.eigen = std::move(eigen);
  if (const auto flips = consistentFlips(region, seed, dirs)) {  // the usual case
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
      for (int i = r.begin(); i != r.end(); ++i)
        if ((*flips)[i]) dirs[i] = -dirs[i];
    });
    out.directions = std::move(dirs);
    return out;
  }
  orientAlongTree(region, seed, dirs);  // connected: consistentFlips() checked it
  const int edgeCount = static_cast<int>(region.edges.size());
  std::vector<char> conflict(edgeCount, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, edgeCount, 4096),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int e = r.begin(); e != r.end(); ++e) {
                        const auto& ends = field.mesh().edges()[region.edges[e]];
                        const int a = region.localVertex(ends[0]), b = region.localVertex(ends[1]);
                        conflict[e] = dirs[a].dot(dirs[b]) < 0;
                      }
                    });
  for (int e = 0; e < edgeCount; ++e) {
    if (!conflict[e]) continue;
    ++out.signConflicts;
    out.conflictEdges.push_back(region.edges[e]);
  }
  out.directions = std::move(dirs);
  return out;
}

}  // namespace tfd::core
