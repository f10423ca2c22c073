#include "core/edit/deform_curve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/edit/deform_paths.h"
#include "core/edit/deformation_map.h"
#include "core/edit/edit_driver.h"
#include "core/edit/edit_verification.h"
#include "core/edit/removal_scenario.h"
#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/region/curve_tube.h"
#include "core/region/region_vertices.h"
#include "core/small_pages.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

/// The picked curve (by the given curves when there are any, mapped to the field's own).
CurvePick resolvePick(const TetMesh& mesh, const DegenerateCurves& all,
                      const DeformCurveOptions& o) {
  if (!o.pick.allFinite()) throw Error("pick: not a finite point");
  if (all.empty()) throw Error("the field has no degenerate curves to deform");
  return resolveCurvePick(mesh, all, o.curves, o.pick);
}

/// Mean length of the region's edges, summed in ascending edge id (flags per mesh edge rather
/// than sorting the six edges of every region tet).
double meanRegionEdge(const TetMesh& mesh, const std::vector<int>& tets) {
  std::vector<unsigned char> in(mesh.edges().size(), 0);
  for (int t : tets)
    for (int e : mesh.tetEdges()[t]) in[e] = 1;
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t e = 0; e < in.size(); ++e) {
    if (!in[e]) continue;
    const auto& ab = mesh.edges()[e];
    sum += (mesh.positions()[ab[0]] - mesh.positions()[ab[1]]).norm();
    ++count;
  }
  return count == 0 ? 0 : sum / double(count);
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

struct DeformSeeds {
  std::vector<int> envelope, seeds;
  std::vector<char> held, anchor;
};

DeformSeeds deformSeeds(const TetMesh& mesh, const DegenerateCurve& curve, const CurvePick& pick,
                        const DeformPaths& paths) {
  const double h = mesh.meanEdgeLength();
  // γ1's tets (the moving points' sources) and γ2's (the minimal envelope), walked from the
  // curve; the envelope's vertices and every vertex within D + h of γ2 (the thick envelope,
  // deformation_map.h) are held by φ, so the seeds are the tets around all of them.
  std::vector<int> curveTets;
  DeformSeeds sd;
  std::vector<char>& anchor = sd.anchor;
  anchor.assign(mesh.vertexCount(), 0);
  for (std::size_t i = 0; i < curve.points.size(); ++i)
    for (int t : tetsOfSource(mesh, curve.sources[i])) {
      if (paths.inGamma1[i])
        curveTets.push_back(t);
      else
        for (int v : mesh.tets()[t]) anchor[v] = 1;  // the rest of the curve stays
    }
  const int startTet = tetsOfSource(mesh, curve.sources[pick.pointIndex]).front();
  sd.envelope = polylineTets(mesh, paths.target, startTet, 0.125 * h);
  const std::vector<int>& envelope = sd.envelope;
  std::vector<int> g1 = polylineTets(mesh, paths.gamma1, startTet, 0.125 * h);
  curveTets.insert(curveTets.end(), g1.begin(), g1.end());
  curveTets.insert(curveTets.end(), envelope.begin(), envelope.end());
  double displacement = 0;
  for (std::size_t i = 0; i < paths.gamma1.size(); ++i)
    displacement = std::max(displacement, (paths.gamma1[i] - paths.gamma2[i]).norm());
  std::vector<char>& held = sd.held;
  held.assign(mesh.vertexCount(), 0);
  for (const TubeVertex& v : findTubeVertices(mesh, paths.target, false, displacement + h).vertices)
    held[v.vertex] = 1;
  std::vector<int>& seeds = sd.seeds;
  seeds = withNeighbourTets(mesh, curveTets);
  for (int v = 0; v < int(mesh.vertexCount()); ++v)
    if (held[v])
      for (int t : mesh.vertexTets(v)) seeds.push_back(t);
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());

  return sd;
}

}  // namespace

std::vector<std::string> DeformCurveReport::lines() const {
  std::vector<std::string> out;
  out.push_back("deformation of " + curve + " (picked " + editNumber(pickDistance) +
                " away): segment of length " + editNumber(length1) + " onto a target of length " +
                editNumber(length2) + ", " + std::to_string(samples) + " samples each");
  out.push_back("region: " + std::to_string(regionTets) + " tets, " +
                std::to_string(regionVertices) + " vertices (" + std::to_string(envelopeVertices) +
                " on the target's envelope, " + std::to_string(solvedVertices) + " solved, " +
                std::to_string(identityVertices) + " held)");
  out.push_back("fold-overs: " + std::to_string(foldOvers) + " (" +
                std::to_string(foldOversOnCurve) + " on the curve); " +
                std::to_string(outsidePreimages) + " preimages outside the mesh");
  out.push_back("Hausdorff distance to the target: " + editNumber(hausdorff) + " (bound " +
                editNumber(tolerance) + ", the region's mean edge length)");
  std::string t = "tries: " + std::to_string(tries.size()) + describeTries(tries);
  out.push_back(t);
  addEditClosingLines(out, seconds, curvesBefore, curvesAfter);
  return out;
}

DeformCurveResult deformCurve(const TensorField& field, const DeformCurveOptions& o,
                              const Progress& progress) {
  const SmallPagesScope smallPages;  // an edit's arrays live for one cook (core/small_pages.h)
  const auto start = std::chrono::steady_clock::now();
  const TetMesh& mesh = field.mesh();
  const EditRetries plan = editRetries(mesh, o.regionDistance, o.retries, o.growFactor);
  progress.report(0, "extracting curves");
  const DegenerateCurves all = extractDegenerateCurves(field, o.extract, progress);
  const CurvePick pick = resolvePick(mesh, all, o);
  const int id = pick.curveId;
  const DegenerateCurve& curve = all.curve(id);
  const double h = mesh.meanEdgeLength();
  const DeformPaths paths = deformPaths(curve, pick, o.target, 0.25 * h);
  DeformCurveReport report;
  report.curve = describeCurve(curve);
  report.pickDistance = pick.distance;
  report.length1 = paths.length1, report.length2 = paths.length2;
  report.samples = int(paths.gamma2.size());
  report.curvesBefore = all.size();

  const DeformSeeds sd = deformSeeds(mesh, curve, pick, paths);
  const std::vector<int>& envelope = sd.envelope;
  const std::vector<char>&held = sd.held, &anchor = sd.anchor;
  const std::vector<int>& seeds = sd.seeds;

  const int targetIds[] = {id};
  const ForbiddenTets forbid = forbidOtherCurves(mesh, all, targetIds);
  const std::vector<unsigned char>& forbidden = forbid.flag;
  const std::vector<int>& owner = forbid.owner;
  auto refuse = [&](int other, const std::string& why) {
    throw Error("no ball region holds the segment and the target " + why + ": it would cut " +
                describeCurve(all.curve(other)));
  };
  for (int s : seeds)
    if (forbidden[s]) refuse(owner[s], "(the target passes too close to another curve)");

  std::optional<DeformCurveResult> result;
  auto attemptTry = [&](int, DeformTry& attempt) {
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
      if (map->foldOversOnCurve > 0) {
        // The tets holding the target have only envelope vertices, which φ maps by the
        // target alone (deformation_map.h): a larger region cannot unfold them.
        attempt.failedCheck = "no fold-over on the curve";
        attempt.detail = std::to_string(map->foldOversOnCurve) + " of " +
                         std::to_string(map->foldOvers) +
                         " inverted tets of the map hold the target; the map there depends on "
                         "the target alone, so no larger region is tried";
        return TryOutcome::Final;
      }
    }
    if (!attempt.failedCheck.empty()) return TryOutcome::Failed;
    TensorField edited(field.meshPtr(), std::move(map->values));
    DegenerateCurves after = extractDegenerateCurves(edited, o.extract, progress);
    std::vector<char> matched;
    const EditVerification v =
        verifyOutside(field, edited, rv.free, region.tets, all, after, targetIds, matched);
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
        attempt.detail = "Hausdorff distance " + editNumber(attempt.hausdorff) + " > " +
                         editNumber(tolerance) + " (mean edge length of the region)";
    }
    if (!attempt.failedCheck.empty()) return TryOutcome::Failed;
    report.regionTets = region.tets.size(), report.regionVertices = rv.vertices.size();
    report.envelopeVertices = map->envelopeVertices;
    report.solvedVertices = map->solvedVertices;
    report.identityVertices = map->identityVertices;
    report.foldOvers = map->foldOvers, report.foldOversOnCurve = map->foldOversOnCurve;
    report.outsidePreimages = map->outsidePreimages;
    report.hausdorff = attempt.hausdorff, report.tolerance = tolerance;
    report.curvesAfter = after.size();
    result = DeformCurveResult{std::move(edited), std::move(after), region.tets, {}};
    return TryOutcome::Verified;
  };
  if (!runEditTries(plan, report.tries, progress, attemptTry))
    failAfterTries<DeformationFailed>("deformation", report.tries);
  report.seconds = secondsSince(start);
  result->report = std::move(report);
  progress.report(1, "verified");
  return std::move(*result);
}

}  // namespace tfd::core
