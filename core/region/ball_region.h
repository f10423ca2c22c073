#pragma once
// A region of tets that is a topological ball around given seed tets (paper §6.1, "Region M",
// used by every topological edit of §6):
//  1. grow: from one seed, add one tet at a time, nearest to the seeds first (distance d_U of
//     the tet's centroid to the nearest seed centroid), each only when the simple-tet test
//     (tet_set.h) says the set stays a ball, until every seed is inside;
//  2. shrink: remove non-seed tets, farthest first, while the set stays a ball;
//  3. grow out: add tets nearest to the shrunk ball first (distance d_U'), up to `distance`.
// A forbidden tet (one holding a point of a degenerate curve not targeted by the edit) is never
// added. Distances are Euclidean between centroids, propagated through face-adjacent tets from
// the nearest source (a Dijkstra front that stops at its bound), so the cost is proportional to
// the region, not to the mesh (plus O(mesh) bytes of flags). Sequential and deterministic
// (ties broken by tet id).
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/progress.h"
#include "core/tet_mesh.h"

namespace tfd::core {

class TetSet;

struct BallRegionOptions {
  double distance = 0;  ///< grow-out distance from the shrunk ball (a length); 0: none
};

struct BallRegion {
  std::vector<int> tets;          ///< ascending; a ball whenever `complete`
  bool complete = false;          ///< every seed is inside
  std::vector<int> missingSeeds;  ///< seeds left outside when not complete, ascending
  /// The forbidden tet nearest to the seeds met while growing to them (−1: none met), and its
  /// distance d_U; when the growth is not complete, the curve there is what stood in the way.
  int blockingTet = -1;
  double blockingDistance = 0;
  std::size_t grownTets = 0;   ///< after step 1
  std::size_t shrunkTets = 0;  ///< after step 2
  /// Why each step stopped, one sentence each.
  std::string growStop, shrinkStop, growOutStop;
};

/// `seeds`: tet ids (any order, duplicates allowed, not empty); `forbidden`: one flag per tet.
/// Throws core::Error for an empty seed list or a bad tet id, core::Cancelled when cancelled.
BallRegion growBallRegion(const TetMesh& mesh, std::span<const int> seeds,
                          const std::vector<unsigned char>& forbidden,
                          const BallRegionOptions& options, const Progress& progress = {});

/// Step 2 on its own: removes tets of `set` listed in `keyed` as (key, tet), farthest first
/// (ties by ascending id), sweep after sweep (at most 64) while the set stays a ball, exactly as
/// testing every listed tet still in the set in every sweep would; returns why it stopped.
std::string shrinkBall(TetSet& set, std::vector<std::pair<double, int>> keyed,
                       const Progress& progress = {});

/// Centroid distance from every tet within `bound` to the nearest source tet's centroid,
/// propagated through faces (infinity beyond `bound`). One entry per mesh tet.
std::vector<double> tetDistances(const TetMesh& mesh, std::span<const int> sources, double bound,
                                 const Progress& progress = {});

}  // namespace tfd::core
