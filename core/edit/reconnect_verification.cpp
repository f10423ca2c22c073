#include "core/edit/reconnect_verification.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "core/edit/reconnect_segments.h"
#include "core/edit/removal_scenario.h"
#include "core/region/region_vertices.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

constexpr double kPointTolerance = 1e-12;
/// Relative to the mean edge length: how far the extraction's fallback perturbation (1e-7 of
/// the tensors around a vertex) can move a point next to the region.
constexpr double kNearTolerance = 1e-6;

std::string pointText(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return buf;
}

struct Piece {
  int curve = -1;
  int first = -1, last = -1;  ///< point indices of the piece's ends
};

/// Per point of the curve: whether it lies on a piece through the region, i.e. a maximal run
/// of points touching the region's tets that holds a point inside it. A run of points only on
/// the region's boundary (a curve grazing a held face, unchanged) is not such a piece.
std::vector<char> throughRegion(const TetMesh& mesh, const DegenerateCurve& c,
                                const std::vector<unsigned char>& inRegion) {
  const int n = int(c.points.size());
  std::vector<PointPlace> place(n);
  for (int i = 0; i < n; ++i) place[i] = pointPlace(mesh, c.sources[i], inRegion);
  std::vector<char> through(n, 0);
  int s0 = 0;
  if (c.closed)
    while (s0 < n && place[s0] != PointPlace::Outside) ++s0;
  if (s0 == n) return std::vector<char>(n, 1);  // a loop wholly in the region
  for (int k = 0; k < n;) {
    const int i = (s0 + k) % n;
    if (place[i] == PointPlace::Outside) {
      ++k;
      continue;
    }
    int len = 0;
    bool inside = false;
    while (k + len < n && place[(s0 + k + len) % n] != PointPlace::Outside)
      inside = inside || place[(s0 + k + len) % n] == PointPlace::Inside, ++len;
    for (int j = 0; j < len; ++j) through[(s0 + k + j) % n] = inside;
    k += len;
  }
  return through;
}

/// The pieces of the curve through the region (runs of `through`); `whole` is set when a
/// closed curve lies in it.
std::vector<Piece> pieces(const DegenerateCurve& c, const std::vector<char>& through, bool& whole) {
  const int n = int(c.points.size());
  std::vector<Piece> out;
  whole = c.closed && std::all_of(through.begin(), through.end(), [](char x) { return x != 0; });
  if (whole) return out;
  int s0 = 0;
  if (c.closed)
    while (through[s0]) ++s0;  // start the scan off the pieces, so no piece wraps
  bool open = false;
  for (int k = 0; k < n; ++k) {
    const int i = (s0 + k) % n;
    if (!through[i]) {
      open = false;
      continue;
    }
    if (!open) out.push_back({c.id, i, i}), open = true;
    out.back().last = i;
  }
  return out;
}

int endAt(std::span<const ReconnectEndpoint, 4> ends, const Vec3& p, double tolerance) {
  for (int i = 0; i < 4; ++i)
    if ((ends[i].position - p).cwiseAbs().maxCoeff() <= tolerance) return i;
  return -1;
}

bool lexLess(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

/// The points of the flagged curves not on a piece through the region, sorted: `far` those whose
/// tets hold no region vertex (the extraction sees exactly the same values there), `near` the
/// others (the extraction's fallback perturbation of a held vertex scales with the tensors around
/// it, some of which are free, so those points may move by that perturbation's size).
void outsidePoints(const TetMesh& mesh, const DegenerateCurves& curves,
                   const std::vector<char>& take, const std::vector<unsigned char>& inRegion,
                   const std::vector<char>& regionVertex, std::vector<Vec3>& far,
                   std::vector<Vec3>& near) {
  for (const DegenerateCurve& c : curves.curves()) {
    if (!take[c.id]) continue;
    const std::vector<char> through = throughRegion(mesh, c, inRegion);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      if (through[i]) continue;
      bool touches = false;
      for (int t : tetsOfSource(mesh, c.sources[i]))
        for (int v : mesh.tets()[t]) touches = touches || regionVertex[v];
      (touches ? near : far).push_back(c.points[i]);
    }
  }
  std::sort(far.begin(), far.end(), lexLess);
  std::sort(near.begin(), near.end(), lexLess);
}

}  // namespace

ReconnectVerification verifyReconnection(
    const TensorField& before, const TensorField& after, std::span<const int> freeVertices,
    std::span<const int> regionTets, const DegenerateCurves& curvesBefore,
    const DegenerateCurves& curvesAfter, std::span<const int> targetIds,
    std::span<const ReconnectEndpoint, 4> ends, const std::array<int, 4>& partner) {
  ReconnectVerification r;
  std::vector<char> matched;
  r.result = verifyOutside(before, after, freeVertices, regionTets, curvesBefore, curvesAfter,
                           targetIds, matched);
  if (!r.result.passed) return r;
  r.result.passed = false;
  auto fail = [&](const char* check, std::string detail) {
    r.result.failedCheck = check;
    r.result.detail = std::move(detail);
    return r;
  };
  const TetMesh& mesh = before.mesh();
  const std::vector<unsigned char> inRegion = tetFlags(mesh, regionTets);
  // Ends and points next to the region: within the extraction's perturbation (see below).
  const double nearTolerance = kNearTolerance * mesh.meanEdgeLength();
  std::vector<Piece> all;
  for (const DegenerateCurve& c : curvesAfter.curves()) {
    if (matched[c.id]) continue;
    bool whole = false;
    const std::vector<Piece> p = pieces(c, throughRegion(mesh, c, inRegion), whole);
    if (whole) return fail("two new curves", describeCurve(c) + " lies inside the region");
    all.insert(all.end(), p.begin(), p.end());
  }
  if (all.size() != 2) {
    std::string where;
    for (std::size_t k = 0; k < all.size() && k < 4; ++k) {
      const DegenerateCurve& c = curvesAfter.curve(all[k].curve);
      where += (k ? "; " : ": ") + pointText(c.points[all[k].first]) + " to " +
               pointText(c.points[all[k].last]);
    }
    return fail("two new curves", std::to_string(all.size()) +
                                      " pieces of curves pass through the region (2 expected)" +
                                      where);
  }
  std::array<char, 4> used{};
  for (int k = 0; k < 2; ++k) {
    const DegenerateCurve& c = curvesAfter.curve(all[k].curve);
    const int a = endAt(ends, c.points[all[k].first], nearTolerance);
    const int b = endAt(ends, c.points[all[k].last], nearTolerance);
    if (a < 0 || b < 0 || a == b)
      return fail("two new curves", describeCurve(c) + " runs through the region from " +
                                        pointText(c.points[all[k].first]) + " to " +
                                        pointText(c.points[all[k].last]) +
                                        ", not from one end to another");
    if (partner[a] != b)
      return fail("ends joined as paired", std::string("a new curve joins ") + endpointName(a) +
                                               " and " + endpointName(b) +
                                               ", which Theorem 6.2 does not pair");
    if (used[a] || used[b]) return fail("ends joined as paired", "an end is joined twice");
    used[a] = used[b] = 1;
    r.newCurves[k] = c.id;
    r.joins[k] = {std::min(a, b), std::max(a, b)};
  }
  std::vector<char> isTarget(curvesBefore.size(), 0), unmatched(curvesAfter.size(), 0);
  for (int id : targetIds) isTarget[id] = 1;
  for (std::size_t i = 0; i < unmatched.size(); ++i) unmatched[i] = !matched[i];
  std::vector<char> regionVertex(mesh.vertexCount(), 0);
  for (int t : regionTets)
    for (int v : mesh.tets()[t]) regionVertex[v] = 1;
  std::vector<Vec3> wasFar, wasNear, nowFar, nowNear;
  outsidePoints(mesh, curvesBefore, isTarget, inRegion, regionVertex, wasFar, wasNear);
  outsidePoints(mesh, curvesAfter, unmatched, inRegion, regionVertex, nowFar, nowNear);
  if (wasFar.size() != nowFar.size() || wasNear.size() != nowNear.size())
    return fail("targets unchanged outside",
                "the reconnected curves have " + std::to_string(nowFar.size() + nowNear.size()) +
                    " points outside the region, the picked curves had " +
                    std::to_string(wasFar.size() + wasNear.size()));
  for (std::size_t i = 0; i < wasFar.size(); ++i)
    if ((wasFar[i] - nowFar[i]).cwiseAbs().maxCoeff() > kPointTolerance)
      return fail("targets unchanged outside",
                  "the point " + pointText(wasFar[i]) + " outside the region moved");
  for (const Vec3& p : wasNear) {
    double best = std::numeric_limits<double>::infinity();
    for (const Vec3& q : nowNear) best = std::min(best, (q - p).cwiseAbs().maxCoeff());
    if (best > nearTolerance)
      return fail(
          "targets unchanged outside",
          "the point " + pointText(p) + " next to the region moved by " + std::to_string(best));
  }
  r.result.passed = true;
  return r;
}

}  // namespace tfd::core
