#include "core/edit/edit_verification.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/edit/removal_scenario.h"
#include "core/region/region_vertices.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

constexpr double kPointTolerance = 1e-12;

std::string pointText(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return buf;
}

bool sameCurve(const DegenerateCurve& a, const DegenerateCurve& b) {
  if (a.closed != b.closed || a.type != b.type || a.points.size() != b.points.size()) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if ((a.points[i] - b.points[i]).cwiseAbs().maxCoeff() > kPointTolerance) return false;
  return true;
}

double distanceToPoints(const DegenerateCurve& c, const std::vector<Vec3>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& p : c.points)
    for (const Vec3& q : points) best = std::min(best, (p - q).squaredNorm());
  return std::sqrt(best);
}

}  // namespace

bool curveTouchesTets(const TetMesh& mesh, const DegenerateCurve& curve,
                      const std::vector<unsigned char>& tetFlag) {
  for (const PointSource& s : curve.sources)
    for (int t : tetsOfSource(mesh, s))
      if (tetFlag[t]) return true;
  return false;
}

EditVerification verifyOutside(const TensorField& before, const TensorField& after,
                               std::span<const int> freeVertices, std::span<const int> regionTets,
                               const DegenerateCurves& curvesBefore,
                               const DegenerateCurves& curvesAfter, std::span<const int> targetIds,
                               std::vector<char>& matched) {
  const TetMesh& mesh = before.mesh();
  EditVerification r;
  auto fail = [&](const char* check, std::string detail) {
    r.failedCheck = check;
    r.detail = std::move(detail);
    return r;
  };
  // 1. Bitwise: compare the bytes, so that −0 vs +0 or a NaN would count as a change.
  std::vector<char> isFree(mesh.vertexCount(), 0);
  for (int v : freeVertices) isFree[v] = 1;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    if (isFree[v]) continue;
    if (std::memcmp(&before.at(int(v)), &after.at(int(v)), sizeof(Tensor)) != 0)
      return fail("outside unchanged", "vertex " + std::to_string(v) + " at " +
                                           pointText(mesh.positions()[v]) +
                                           " is not free but changed");
  }
  const std::vector<unsigned char> inRegion = tetFlags(mesh, regionTets);
  std::vector<char> isTarget(curvesBefore.size(), 0);
  for (int id : targetIds) isTarget[id] = 1;
  // 2. Untouched curves, matched one to one.
  matched.assign(curvesAfter.size(), 0);
  for (const DegenerateCurve& c : curvesBefore.curves()) {
    if (isTarget[c.id]) continue;
    if (curveTouchesTets(mesh, c, inRegion))
      return fail("untouched curves unchanged",
                  describeCurve(c) + " is not a target but passes through the region");
    bool found = false;
    for (const DegenerateCurve& d : curvesAfter.curves()) {
      if (!matched[d.id] && sameCurve(c, d)) {
        matched[d.id] = found = true;
        break;
      }
    }
    if (!found)
      return fail("untouched curves unchanged",
                  describeCurve(c) + ", which does not touch the region, changed or vanished");
  }
  for (const DegenerateCurve& d : curvesAfter.curves())
    if (!matched[d.id] && !curveTouchesTets(mesh, d, inRegion))
      return fail("untouched curves unchanged", describeCurve(d) + " appeared outside the region");
  r.passed = true;
  return r;
}

EditVerification verifyEdit(const TensorField& before, const TensorField& after,
                            std::span<const int> freeVertices, std::span<const int> regionTets,
                            const DegenerateCurves& curvesBefore,
                            const DegenerateCurves& curvesAfter, std::span<const int> targetIds) {
  std::vector<char> matched;
  EditVerification r = verifyOutside(before, after, freeVertices, regionTets, curvesBefore,
                                     curvesAfter, targetIds, matched);
  if (!r.passed) return r;
  r.passed = false;
  auto fail = [&](const char* check, std::string detail) {
    r.failedCheck = check;
    r.detail = std::move(detail);
    return r;
  };
  std::vector<Vec3> targetPoints;
  for (int id : targetIds) {
    const auto& pts = curvesBefore.curve(id).points;
    targetPoints.insert(targetPoints.end(), pts.begin(), pts.end());
  }
  const TetMesh& mesh = before.mesh();
  // 3 and 4. Curves after the edit that are not untouched ones (all touch the region).
  const double near = 2 * mesh.meanEdgeLength();
  for (const DegenerateCurve& d : curvesAfter.curves()) {
    if (matched[d.id]) continue;
    if (distanceToPoints(d, targetPoints) <= near)
      return fail("targets gone", describeCurve(d) + " (" + std::to_string(d.points.size()) +
                                      " points) remains where a target was");
    return fail("nothing new in the region", describeCurve(d) + " (" +
                                                 std::to_string(d.points.size()) +
                                                 " points) appeared in the region");
  }
  r.passed = true;
  return r;
}

}  // namespace tfd::core
