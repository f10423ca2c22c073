#include "core/edit/deform_curve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/edit/deform_paths.h"
#include "core/edit/deformation_map.h"
#include "core/edit/edit_verification.h"
#include "core/edit/removal_scenario.h"
#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/region/curve_tube.h"
#include "core/region/region_vertices.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::vector<int> sourceTets(const TetMesh& mesh, const DegenerateCurve& c) {
  std::vector<int> tets;
  for (const PointSource& s : c.sources)
    for (int t : tetsOfSource(mesh, s)) tets.push_back(t);
  return tets;
}

/// The picked curve (by the given curves when there are any, mapped to the field's own).
std::pair<int, CurvePick> resolvePick(const TetMesh& mesh, const DegenerateCurves& all,
                                      const DeformCurveOptions& o) {
  if (!o.pick.allFinite()) throw Error("pick: not a finite point");
  if (all.empty()) throw Error("the field has no degenerate curves to deform");
  const DegenerateCurves& pickFrom = o.curves ? *o.curves : all;
  const std::optional<CurvePick> seen = pickFrom.pick(o.pick);
  if (!seen) throw Error("curves: the given curves are empty");
  if (!o.curves) return {seen->curveId, *seen};
  const CurvePick mapped = *all.pick(seen->position);
  const double tolerance = 1e-9 * (mesh.boundsMax() - mesh.boundsMin()).norm();
  if (mapped.distance > tolerance)
    throw Error("curves: the given curves do not belong to the field (the picked curve is " +
                number(mapped.distance) + " from every curve of the field)");
  CurvePick p = mapped;
  p.distance = seen->distance;
  return {mapped.curveId, p};
}

/// Adds the tets around every vertex of `tets`; ascending, unique.
std::vector<int> withNeighbours(const TetMesh& mesh, const std::vector<int>& tets) {
  std::vector<int> out;
  for (int t : tets)
    for (int v : mesh.tets()[t])
      for (int n : mesh.vertexTets(v)) out.push_back(n);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double meanRegionEdge(const TetMesh& mesh, const std::vector<int>& tets) {
  std::vector<int> edges;
  for (int t : tets)
    for (int e : mesh.tetEdges()[t]) edges.push_back(e);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum = 0;
  for (int e : edges) {
    const auto& ab = mesh.edges()[e];
    sum += (mesh.positions()[ab[0]] - mesh.positions()[ab[1]]).norm();
  }
  return edges.empty() ? 0 : sum / double(edges.size());
}

/// Hausdorff distance, over the region, between the new curve and the expected course (γ2 and
/// the rest of the curve): the new curve's points in region tets against the expected
/// polylines, and γ2's samples against the new curve.
double courseDistance(const TetMesh& mesh, const DegenerateCurve& now, const DeformPaths& paths,
                      const std::vector<unsigned char>& inRegion) {
  double h = 0;
  for (std::size_t i = 0; i < now.points.size(); ++i) {
    bool inside = false;
    for (int t : tetsOfSource(mesh, now.sources[i])) inside = inside || inRegion[t];
    if (!inside) continue;
    double d = distanceToPolyline(now.points[i], paths.target);
    for (const auto& r : paths.rest) d = std::min(d, distanceToPolyline(now.points[i], r));
    h = std::max(h, d);
  }
  std::vector<Vec3> line = now.points;
  if (now.closed && line.size() > 2) line.push_back(line.front());
  for (const Vec3& q : paths.gamma2) h = std::max(h, distanceToPolyline(q, line));
  return h;
}

}  // namespace

std::vector<std::string> DeformCurveReport::lines() const {
  std::vector<std::string> out;
  out.push_back("deformation of " + curve + " (picked " + number(pickDistance) +
                " away): segment of length " + number(length1) + " onto a target of length " +
                number(length2) + ", " + std::to_string(samples) + " samples each");
  out.push_back("region: " + std::to_string(regionTets) + " tets, " +
                std::to_string(regionVertices) + " vertices (" + std::to_string(envelopeVertices) +
                " on the target's envelope, " + std::to_string(solvedVertices) + " solved, " +
                std::to_string(identityVertices) + " held)");
  out.push_back("fold-overs: " + std::to_string(foldOvers) + " (" +
                std::to_string(foldOversOnCurve) + " on the curve); " +
                std::to_string(outsidePreimages) + " preimages outside the mesh");
  out.push_back("Hausdorff distance to the target: " + number(hausdorff) + " (bound " +
                number(tolerance) + ", the region's mean edge length)");
  std::string t = "tries: " + std::to_string(tries.size());
  for (std::size_t i = 0; i < tries.size(); ++i)
    t +=
        "; #" + std::to_string(i + 1) + " distance " + number(tries[i].distance) + ", " +
        std::to_string(tries[i].regionTets) + " tets: " +
        (tries[i].failedCheck.empty() ? "verified"
                                      : tries[i].failedCheck + " failed (" + tries[i].detail + ")");
  out.push_back(t);
  out.push_back("time " + number(seconds) + " s");
  out.push_back(std::to_string(curvesBefore) + " curves -> " + std::to_string(curvesAfter));
  return out;
}

DeformCurveResult deformCurve(const TensorField& field, const DeformCurveOptions& o,
                              const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const TetMesh& mesh = field.mesh();
  if (!(o.retries >= 0) || !(o.growFactor > 1) || !std::isfinite(o.regionDistance))
    throw Error("retries must be ≥ 0, the grow factor > 1 and region_distance finite");
  progress.report(0, "extracting curves");
  const DegenerateCurves all = extractDegenerateCurves(field, o.extract, progress);
  const auto [id, pick] = resolvePick(mesh, all, o);
  const DegenerateCurve& curve = all.curve(id);
  const double h = mesh.meanEdgeLength();
  const DeformPaths paths = deformPaths(curve, pick, o.target, 0.25 * h);
  DeformCurveReport report;
  report.curve = describeCurve(curve);
  report.pickDistance = pick.distance;
  report.length1 = paths.length1, report.length2 = paths.length2;
  report.samples = int(paths.gamma2.size());
  report.curvesBefore = all.size();

  // γ1's tets (the moving points' sources) and γ2's (the minimal envelope), walked from the
  // curve; the envelope's vertices and every vertex within D + h of γ2 (the thick envelope,
  // deformation_map.h) are held by φ, so the seeds are the tets around all of them.
  std::vector<int> curveTets;
  std::vector<char> anchor(mesh.vertexCount(), 0);
  for (std::size_t i = 0; i < curve.points.size(); ++i)
    for (int t : tetsOfSource(mesh, curve.sources[i])) {
      if (paths.inGamma1[i])
        curveTets.push_back(t);
      else
        for (int v : mesh.tets()[t]) anchor[v] = 1;  // the rest of the curve stays
    }
  const int startTet = tetsOfSource(mesh, curve.sources[pick.pointIndex]).front();
  const std::vector<int> envelope = polylineTets(mesh, paths.target, startTet, 0.125 * h);
  std::vector<int> g1 = polylineTets(mesh, paths.gamma1, startTet, 0.125 * h);
  curveTets.insert(curveTets.end(), g1.begin(), g1.end());
  curveTets.insert(curveTets.end(), envelope.begin(), envelope.end());
  double displacement = 0;
  for (std::size_t i = 0; i < paths.gamma1.size(); ++i)
    displacement = std::max(displacement, (paths.gamma1[i] - paths.gamma2[i]).norm());
  std::vector<char> held(mesh.vertexCount(), 0);
  for (const TubeVertex& v : findTubeVertices(mesh, paths.target, false, displacement + h).vertices)
    held[v.vertex] = 1;
  std::vector<int> seeds = withNeighbours(mesh, curveTets);
  for (int v = 0; v < int(mesh.vertexCount()); ++v)
    if (held[v])
      for (int t : mesh.vertexTets(v)) seeds.push_back(t);
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());

  std::vector<unsigned char> forbidden(mesh.tetCount(), 0);
  std::vector<int> owner(mesh.tetCount(), -1);
  for (const DegenerateCurve& c : all.curves()) {
    if (c.id == id) continue;
    for (int n : withNeighbours(mesh, sourceTets(mesh, c)))
      if (!forbidden[n]) forbidden[n] = 1, owner[n] = c.id;
  }
  auto refuse = [&](int other, const std::string& why) {
    throw Error("no ball region holds the segment and the target " + why + ": it would cut " +
                describeCurve(all.curve(other)));
  };
  for (int s : seeds)
    if (forbidden[s]) refuse(owner[s], "(the target passes too close to another curve)");

  const double radius = 0.5 * (mesh.boundsMax() - mesh.boundsMin()).norm();
  const double distance0 = o.regionDistance < 0 ? 0.3 * radius : o.regionDistance;
  for (int k = 0; k <= o.retries; ++k) {
    DeformTry attempt;
    attempt.distance = distance0 * std::pow(o.growFactor, k);
    progress.report(0.1 + 0.8 * k / (o.retries + 1), "growing the region");
    const BallRegion region = growBallRegion(mesh, seeds, forbidden, {attempt.distance}, progress);
    if (!region.complete) {
      if (region.blockingTet >= 0) refuse(owner[region.blockingTet], "");
      throw Error("no ball region holds the segment and the target: " + region.growStop);
    }
    attempt.regionTets = region.tets.size();
    const BallCheck ball = checkTopologicalBall(mesh, region.tets);
    const RegionVertices rv = regionVertices(mesh, region.tets);
    std::optional<DeformedField> map;
    if (!ball.ball) {
      attempt.failedCheck = "region is a ball", attempt.detail = ball.problem;
    } else {
      map = deformField(field, region.tets, rv, envelope, held, anchor, paths.gamma1, paths.gamma2,
                        progress);
      attempt.foldOvers = map->foldOvers, attempt.foldOversOnCurve = map->foldOversOnCurve;
      if (map->foldOversOnCurve > 0)
        attempt.failedCheck = "no fold-over on the curve",
        attempt.detail = std::to_string(map->foldOversOnCurve) + " of " +
                         std::to_string(map->foldOvers) +
                         " inverted tets of the map hold the target";
    }
    if (attempt.failedCheck.empty()) {
      TensorField edited(field.meshPtr(), std::move(map->values));
      DegenerateCurves after = extractDegenerateCurves(edited, o.extract, progress);
      std::vector<char> matched;
      const int targets[] = {id};
      const EditVerification v =
          verifyOutside(field, edited, rv.free, region.tets, all, after, targets, matched);
      attempt.failedCheck = v.failedCheck, attempt.detail = v.detail;
      const DegenerateCurve* moved = nullptr;
      int inside = 0;
      for (const DegenerateCurve& c : after.curves())
        if (!matched[c.id]) moved = &c, ++inside;
      const double tolerance = meanRegionEdge(mesh, region.tets);
      if (v.passed && inside != 1) {
        attempt.failedCheck = "one curve in the region";
        attempt.detail = std::to_string(inside) + " curves pass through the region";
      } else if (v.passed && moved->type != curve.type) {
        attempt.failedCheck = "one curve in the region";
        attempt.detail = "the curve in the region is " + describeCurve(*moved) + ", not of type " +
                         std::string(toString(curve.type));
      } else if (v.passed) {
        attempt.hausdorff = courseDistance(mesh, *moved, paths, tetFlags(mesh, region.tets));
        if (!(attempt.hausdorff <= tolerance))
          attempt.failedCheck = "follows the target",
          attempt.detail = "Hausdorff distance " + number(attempt.hausdorff) + " > " +
                           number(tolerance) + " (mean edge length of the region)";
      }
      if (attempt.failedCheck.empty()) {
        report.tries.push_back(attempt);
        report.regionTets = region.tets.size(), report.regionVertices = rv.vertices.size();
        report.envelopeVertices = map->envelopeVertices;
        report.solvedVertices = map->solvedVertices;
        report.identityVertices = map->identityVertices;
        report.foldOvers = map->foldOvers, report.foldOversOnCurve = map->foldOversOnCurve;
        report.outsidePreimages = map->outsidePreimages;
        report.hausdorff = attempt.hausdorff, report.tolerance = tolerance;
        report.curvesAfter = after.size();
        report.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress.report(1, "verified");
        return {std::move(edited), std::move(after), region.tets, std::move(report)};
      }
    }
    report.tries.push_back(attempt);
    if (k > 0 && report.tries[k - 1].regionTets == attempt.regionTets) break;  // cannot grow
  }
  const DeformTry& last = report.tries.back();
  std::string earlier;
  for (std::size_t i = 0; i + 1 < report.tries.size(); ++i)
    earlier += "; try " + std::to_string(i + 1) + " (" +
               std::to_string(report.tries[i].regionTets) +
               " tets): " + report.tries[i].failedCheck + " (" + report.tries[i].detail + ")";
  throw DeformationFailed("deformation failed after " + std::to_string(report.tries.size()) +
                          " tries: check '" + last.failedCheck + "' failed (" + last.detail +
                          "); last region " + std::to_string(last.regionTets) + " tets (distance " +
                          number(last.distance) + ")" + earlier);
}

}  // namespace tfd::core
