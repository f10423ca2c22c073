#include "core/edit/edit_driver.h"

#include <algorithm>
#include <cstdio>

#include "core/topology/curve_tets.h"

namespace tfd::core {

std::string editNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void addEditClosingLines(std::vector<std::string>& out, double seconds, std::size_t curvesBefore,
                         std::size_t curvesAfter) {
  out.push_back("time " + editNumber(seconds) + " s");
  out.push_back(std::to_string(curvesBefore) + " curves -> " + std::to_string(curvesAfter));
}

std::vector<int> curveSourceTets(const TetMesh& mesh, const DegenerateCurve& c) {
  std::vector<int> tets;
  for (const PointSource& s : c.sources)
    for (int t : tetsOfSource(mesh, s)) tets.push_back(t);
  return tets;
}

std::vector<int> withNeighbourTets(const TetMesh& mesh, std::span<const int> tets) {
  std::vector<int> out;
  for (int t : tets)
    for (int v : mesh.tets()[t])
      for (int n : mesh.vertexTets(v)) out.push_back(n);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

CurvePick resolveCurvePick(const TetMesh& mesh, const DegenerateCurves& all,
                           const DegenerateCurves* given, const Vec3& point) {
  const DegenerateCurves& pickFrom = given ? *given : all;
  const std::optional<CurvePick> seen = pickFrom.pick(point);
  if (!seen) throw Error("curves: the given curves are empty");
  if (!given) return *seen;
  const CurvePick mapped = *all.pick(seen->position);
  const double tolerance = 1e-9 * (mesh.boundsMax() - mesh.boundsMin()).norm();
  if (mapped.distance > tolerance)
    throw Error("curves: the given curves do not belong to the field (the picked curve is " +
                editNumber(mapped.distance) + " from every curve of the field)");
  CurvePick p = mapped;
  p.distance = seen->distance;
  return p;
}

ForbiddenTets forbidOtherCurves(const TetMesh& mesh, const DegenerateCurves& all,
                                std::span<const int> targetIds) {
  ForbiddenTets f{std::vector<unsigned char>(mesh.tetCount(), 0),
                  std::vector<int>(mesh.tetCount(), -1)};
  for (const DegenerateCurve& c : all.curves()) {
    if (std::find(targetIds.begin(), targetIds.end(), c.id) != targetIds.end()) continue;
    for (int t : curveSourceTets(mesh, c))
      for (int v : mesh.tets()[t])
        for (int n : mesh.vertexTets(v)) f.add(n, c.id);
  }
  return f;
}

EditRetries editRetries(const TetMesh& mesh, double regionDistance, int retries,
                        double growFactor) {
  if (!(retries >= 0) || !(growFactor > 1) || !std::isfinite(regionDistance))
    throw Error("retries must be ≥ 0, the grow factor > 1 and region_distance finite");
  const double radius = 0.5 * (mesh.boundsMax() - mesh.boundsMin()).norm();
  return {regionDistance < 0 ? 0.3 * radius : regionDistance, growFactor, retries};
}

}  // namespace tfd::core
