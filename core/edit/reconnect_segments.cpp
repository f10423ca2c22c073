#include "core/edit/reconnect_segments.h"

#include <algorithm>
#include <cmath>

#include "core/edit/removal_scenario.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

struct Walk {
  int end = -1;           ///< point index on the boundary
  std::vector<int> path;  ///< from the pick to the end, both included
  std::string problem;
};

/// Follows the curve from `start` in direction `dir` (±1) while its points are inside.
Walk walk(const TetMesh& mesh, const DegenerateCurve& c, int start, int dir,
          const std::vector<unsigned char>& inRegion) {
  Walk w;
  const int n = int(c.points.size());
  int j = start;
  for (int steps = 0;; ++steps) {
    w.path.push_back(j);
    const PointPlace place = pointPlace(mesh, c.sources[j], inRegion);
    if (place == PointPlace::Boundary && j != start) {
      w.end = j;
      return w;
    }
    if (place != PointPlace::Inside) {
      w.problem = "the picked point of " + describeCurve(c) + " is not inside the region";
      return w;
    }
    int next = j + dir;
    if (c.closed) next = (next + n) % n;
    if (next < 0 || next >= n) {
      w.problem = describeCurve(c) +
                  " ends on the domain surface inside the region (a segment must leave the "
                  "region through its held boundary: move the pick or shorten segment_length)";
      return w;
    }
    if (steps > n) {
      w.problem = "the whole loop " + describeCurve(c) + " is inside the region";
      return w;
    }
    j = next;
  }
}

/// The non-repeating eigenvector at curve point j, oriented like the vectorised one at the
/// region vertices of its source.
Vec3 orientedEigenvector(const TetMesh& mesh, const DegenerateCurve& c, int j,
                         const RegionComplex& region, const VectorisedEigenvector& vec) {
  Vec3 v = c.eigenvectors[j];
  double agree = 0;
  for (int m : sourceVertices(mesh, c.sources[j]))
    if (const int l = region.localVertex(m); l >= 0) agree += v.dot(vec.directions[l]);
  return agree < 0 ? Vec3(-v) : v;
}

/// Lemma 6.1's charge of the segment's backward end (the curve followed forward, into the
/// region): a vote of the segment's wedge and trisector points, each (V · t > 0) XOR wedge with
/// t the forward tangent, weighted by |V · t|. Both the pattern and the sign of V · t flip at a
/// transition point, so every point votes alike where it is classified right; the weight
/// silences the points next to a transition point (V · t ≈ 0). −1 when no point votes.
int votedCharge(const TetMesh& mesh, const DegenerateCurve& c, const std::vector<int>& points,
                const RegionComplex& region, const VectorisedEigenvector& vec) {
  double vote = 0;
  for (int j : points) {
    if (c.patterns[j] == DegeneratePattern::Transition) continue;
    const double a = orientedEigenvector(mesh, c, j, region, vec).dot(c.tangents[j]);
    const bool charge = (a > 0) != (c.patterns[j] == DegeneratePattern::Wedge);
    vote += charge ? std::abs(a) : -std::abs(a);
  }
  return vote == 0 ? -1 : vote > 0 ? 1 : 0;
}

ReconnectEndpoint classify(const TetMesh& mesh, const DegenerateCurve& c, int segment, int j,
                           int inner, int dir, const std::vector<unsigned char>& inRegion,
                           const RegionComplex& region, const VectorisedEigenvector& vec) {
  ReconnectEndpoint e;
  e.curveId = c.id, e.segment = segment, e.pointIndex = j, e.position = c.points[j];
  e.pattern = c.patterns[j] == DegeneratePattern::Transition ? c.patterns[inner] : c.patterns[j];
  if (e.pattern == DegeneratePattern::Transition) e.pattern = DegeneratePattern::Wedge;
  // The tangent into the region: against the walk's direction.
  Vec3 tIn = -double(dir) * c.tangents[j];
  if (!(tIn.squaredNorm() > 0.5)) tIn = (c.points[inner] - c.points[j]).normalized();
  // The non-repeating eigenvector at the end, oriented like the vectorised one around it.
  const Vec3 v = orientedEigenvector(mesh, c, j, region, vec);
  e.alignment = v.dot(tIn);
  e.incoming = e.alignment > 0;
  if (c.sources[j].kind == PointSource::Kind::Face) {
    const auto& f = mesh.faces()[c.sources[j].id];
    const auto& ft = mesh.faceTets()[c.sources[j].id];
    const int inside = ft[0] >= 0 && inRegion[ft[0]] ? ft[0] : ft[1];
    int apex = -1;
    for (int m : mesh.tets()[inside])
      if (m != f[0] && m != f[1] && m != f[2]) apex = m;
    const auto& P = mesh.positions();
    Vec3 n = (P[f[1]] - P[f[0]]).cross(P[f[2]] - P[f[0]]);
    if (n.dot(P[apex] - P[f[0]]) > 0) n = -n;  // out of the region
    e.faceIncoming = v.dot(n) < 0 ? 1 : 0;
  }
  return e;
}

}  // namespace

PointPlace pointPlace(const TetMesh& mesh, const PointSource& source,
                      const std::vector<unsigned char>& inRegion) {
  const std::vector<int> tets = tetsOfSource(mesh, source);
  std::size_t in = 0;
  for (int t : tets) in += inRegion[t] != 0;
  if (in == 0) return PointPlace::Outside;
  return in == tets.size() ? PointPlace::Inside : PointPlace::Boundary;
}

std::vector<int> sourceVertices(const TetMesh& mesh, const PointSource& s) {
  switch (s.kind) {
    case PointSource::Kind::Face: {
      const auto& f = mesh.faces()[s.id];
      return {f[0], f[1], f[2]};
    }
    case PointSource::Kind::Edge: {
      const auto& e = mesh.edges()[s.id];
      return {e[0], e[1]};
    }
    case PointSource::Kind::Vertex:
      return {s.id};
    case PointSource::Kind::Tet: {
      const auto& t = mesh.tets()[s.id];
      return {t[0], t[1], t[2], t[3]};
    }
  }
  return {};
}

ReconnectSegments findReconnectSegments(const TetMesh& mesh, const DegenerateCurves& curves,
                                        std::span<const std::array<int, 2>, 2> picks,
                                        const std::vector<unsigned char>& inRegion,
                                        const RegionComplex& region,
                                        const VectorisedEigenvector& vec) {
  ReconnectSegments r;
  for (int s = 0; s < 2; ++s) {
    const DegenerateCurve& c = curves.curve(picks[s][0]);
    const Walk back = walk(mesh, c, picks[s][1], -1, inRegion);
    const Walk fwd = walk(mesh, c, picks[s][1], +1, inRegion);
    r.problem = !back.problem.empty() ? back.problem : fwd.problem;
    if (!r.problem.empty()) return r;
    std::vector<int>& pts = r.points[s];
    pts.assign(back.path.rbegin(), back.path.rend());
    pts.insert(pts.end(), fwd.path.begin() + 1, fwd.path.end());
    r.ends[2 * s] =
        classify(mesh, c, s, back.end, back.path[back.path.size() - 2], -1, inRegion, region, vec);
    r.ends[2 * s + 1] =
        classify(mesh, c, s, fwd.end, fwd.path[fwd.path.size() - 2], +1, inRegion, region, vec);
    if (const int q = votedCharge(mesh, c, pts, region, vec); q >= 0) {
      r.ends[2 * s].votedCharge = q;
      r.ends[2 * s + 1].votedCharge = 1 - q;
    }
  }
  if (picks[0][0] == picks[1][0]) {
    std::vector<int> a = r.points[0], b = r.points[1];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::vector<int> common;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    if (!common.empty())
      r.problem = "both picks lie on the same segment of " +
                  describeCurve(curves.curve(picks[0][0])) +
                  " inside the region: pick two places further apart or shorten segment_length";
  }
  return r;
}

}  // namespace tfd::core
