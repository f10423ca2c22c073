#include "core/edit/smooth_directions.h"

#include <algorithm>
#include <cmath>

#include "core/edit/angle_field.h"
#include "core/error.h"

namespace tfd::core {

DirectionRepair repairRoughDirections(const TetMesh& mesh, const RegionComplex& region,
                                      const std::vector<Vec3>& directions,
                                      const std::vector<char>& held, const std::vector<char>& weak,
                                      double maxTurn, int rings, const Progress& progress) {
  const int n = static_cast<int>(region.vertices.size());
  if (directions.size() != static_cast<std::size_t>(n) || held.size() != directions.size() ||
      weak.size() != directions.size())
    throw Error("direction repair: directions, held or weak flags do not match the region");
  DirectionRepair r;
  r.directions = directions;
  // Rough edges: their two ends start the patch.
  std::vector<int> ring(n, -1), queue;
  for (int a = 0; a < n; ++a) {
    for (int k = region.start[a]; k < region.start[a + 1]; ++k) {
      const int b = region.neighbour[k];
      if (b < a) continue;
      const double turn = std::acos(std::clamp(directions[a].dot(directions[b]), -1.0, 1.0));
      r.maxTurnBefore = std::max(r.maxTurnBefore, turn);
      if (!(turn > maxTurn) || !(weak[a] || weak[b])) continue;
      ++r.roughEdges;
      for (int v : {a, b})
        if (ring[v] < 0) ring[v] = 0, queue.push_back(v);
    }
  }
  if (queue.empty()) return r;
  std::sort(queue.begin(), queue.end());
  for (std::size_t h = 0; h < queue.size(); ++h) {
    const int a = queue[h];
    if (ring[a] >= rings) continue;
    for (int k = region.start[a]; k < region.start[a + 1]; ++k) {
      const int b = region.neighbour[k];
      if (ring[b] < 0) ring[b] = ring[a] + 1, queue.push_back(b);
    }
  }
  std::vector<char> fixed(n, 1);
  for (int a : queue)
    if (!held[a]) fixed[a] = 0, ++r.solvedVertices;
  if (r.solvedVertices == 0) return r;
  progress.throwIfCancelled();

  // Equation 1 per component with zero jumps; the initial guess is N itself.
  std::vector<double> values(static_cast<std::size_t>(n) * 3);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) values[i * 3 + c] = directions[i][c];
  const std::vector<double> jumps(region.edges.size() * 3, 0.0);
  solveJumpLaplacian(mesh, region, fixed, jumps, values, 3, {}, progress);
  for (int i = 0; i < n; ++i) {
    if (fixed[i]) continue;
    const Vec3 v(values[i * 3], values[i * 3 + 1], values[i * 3 + 2]);
    // A vanishing harmonic vector (N would have a zero) keeps the given direction: the edit's
    // verification then judges the result.
    if (v.norm() > 1e-6) r.directions[i] = v.normalized();
  }
  return r;
}

}  // namespace tfd::core
