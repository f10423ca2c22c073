#include "core/edit/vectorise_eigenvector.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <functional>
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
/// returns how many it reached (all of them unless the region is not connected).
int orientAlongTree(const RegionComplex& region, int seed, std::vector<Vec3>& dirs) {
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
  int reached = 1;
  while (!queue.empty()) {
    const auto [weight, negTo, from] = queue.top();
    queue.pop();
    const int to = -negTo;
    if (done[to]) continue;
    done[to] = 1;
    ++reached;
    if (dirs[from].dot(dirs[to]) < 0) dirs[to] = -dirs[to];
    push(to);
  }
  return reached;
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
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 256), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) {
      const Tensor a = field.at(region.vertices[i]).deviator();
      const EigenDecomposition d = eigenDecompose(a);
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
  if (orientAlongTree(region, seed, dirs) != n) {
    throw Error("vectorise eigenvector: the region is not connected (" +
                std::to_string(region.components()) + " pieces)");
  }

  VectorisedEigenvector out;
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
  out.seed = region.vertices[seed];
  out.vertices = region.vertices;
  out.directions = std::move(dirs);
  return out;
}

}  // namespace tfd::core
