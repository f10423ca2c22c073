#include "core/edit/remove_curves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/edit/angle_defects.h"
#include "core/edit/edit_driver.h"
#include "core/edit/edit_verification.h"
#include "core/edit/region_examination.h"
#include "core/edit/remove_two_loops.h"
#include "core/edit/singularity_free_field.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/region/curve_tube.h"
#include "core/region/region_vertices.h"
#include "core/small_pages.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

/// Regrowths of one removal around sign conflicts, and around angle defects, before they are
/// left to fail the try.
constexpr int kConflictRegrowths = 8;
constexpr int kDefectRegrowths = 8;

/// Shortest distance between the points of `a` and the polyline of `b`.
double curveDistance(const DegenerateCurve& a, const DegenerateCurve& b) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = b.points.size();
  for (const Vec3& p : a.points) {
    if (n == 1) best = std::min(best, (p - b.points[0]).norm());
    for (std::size_t i = 0; i < b.segmentCount(); ++i) {
      const Vec3 &u = b.points[i], &v = b.points[(i + 1) % n];
      const double t = closestSegmentParameter(p, u, v);
      best = std::min(best, (p - ((1 - t) * u + t * v)).norm());
    }
  }
  return best;
}

struct Targets {
  std::vector<int> ids;
  std::vector<const DegenerateCurve*> curves;
  std::vector<double> pickDistances;
};

Targets resolveTargets(const TetMesh& mesh, const DegenerateCurves& all,
                       const RemoveCurvesOptions& o) {
  if (o.picks.empty() || o.picks.size() > 2)
    throw Error("picks: give one or two points (got " + std::to_string(o.picks.size()) + ")");
  if (all.empty()) throw Error("the field has no degenerate curves to remove");
  Targets t;
  for (const Vec3& p : o.picks) {
    if (!p.allFinite()) throw Error("picks: a pick is not a finite point");
    const CurvePick pick = resolveCurvePick(mesh, all, o.curves, p);
    const int id = pick.curveId;
    if (std::find(t.ids.begin(), t.ids.end(), id) != t.ids.end()) continue;
    t.ids.push_back(id);
    t.curves.push_back(&all.curve(id));
    t.pickDistances.push_back(pick.distance);
  }
  return t;
}

/// The tets holding the targets' points, ascending.
std::vector<int> targetTets(const TetMesh& mesh, const Targets& targets) {
  std::vector<int> tets;
  for (const DegenerateCurve* c : targets.curves) {
    const std::vector<int> own = curveSourceTets(mesh, *c);
    tets.insert(tets.end(), own.begin(), own.end());
  }
  std::sort(tets.begin(), tets.end());
  tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
  return tets;
}

/// Seeds: the tets holding the targets and every tet around their vertices.
std::vector<int> seedTets(const TetMesh& mesh, const Targets& targets) {
  return withNeighbourTets(mesh, targetTets(mesh, targets));
}

/// Owner code of tets forbidden around a sign-conflict edge: −2 − edge id (curves are ≥ 0),
/// and around an angle-defect face: −2 − edge count − face id.
int conflictOwner(int edge) { return -2 - edge; }
int defectOwner(const TetMesh& mesh, int face) {
  return -2 - static_cast<int>(mesh.edges().size()) - face;
}

[[noreturn]] void refuseCut(const TetMesh& mesh, const DegenerateCurves& all,
                            const Targets& targets, DegenerateType type, int owner) {
  const int edgeCount = static_cast<int>(mesh.edges().size());
  if (owner <= -2) {
    const bool defect = -2 - owner >= edgeCount;
    Vec3 at = Vec3::Zero();
    if (defect) {
      for (int v : mesh.faces()[-2 - edgeCount - owner]) at += mesh.positions()[v] / 3;
    } else {
      for (int v : mesh.edges()[-2 - owner]) at += mesh.positions()[v] / 2;
    }
    std::string names;
    for (const DegenerateCurve* c : targets.curves)
      names += (names.empty() ? "" : " and ") + describeCurve(*c);
    const std::string place = "no ball region around " + names + " avoids the place near (" +
                              editNumber(at.x()) + ", " + editNumber(at.y()) + ", " +
                              editNumber(at.z()) + ") where the ";
    if (defect)
      throw RemovalRefused(place +
                           "medium eigenvector turns by half a turn around a face of the region's "
                           "boundary (a degenerate point of the targets' type that the mesh does "
                           "not resolve into a curve, §6.3 cannot hold it fixed)");
    throw RemovalRefused(place + (type == DegenerateType::Linear ? "major" : "minor") +
                         " eigenvector cannot be oriented (a degenerate point of the other type "
                         "that the mesh does not resolve into a curve)");
  }
  const DegenerateCurve& other = all.curve(owner);
  double d = std::numeric_limits<double>::infinity();
  std::string names;
  for (const DegenerateCurve* c : targets.curves) {
    d = std::min(d, curveDistance(*c, other));
    names += (names.empty() ? "" : " and ") + describeCurve(*c);
  }
  throw RemovalRefused("no ball region around " + names + " avoids " + describeCurve(other) + ", " +
                       editNumber(d) + " away: the region would have to cut it");
}

/// Forbids one more ring of tets (every tet around a vertex of a forbidden tet not caused by
/// a sign conflict) around the other curves, unless that would take a seed: returns whether
/// it did.
bool widenAroundCurves(const TetMesh& mesh, const std::vector<int>& seeds,
                       std::vector<unsigned char>& forbidden, std::vector<int>& owner) {
  std::vector<std::pair<int, int>> added;  // (tet, owner)
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    if (!forbidden[t] || owner[t] < 0) continue;
    for (int v : mesh.tets()[t])
      for (int n : mesh.vertexTets(v))
        if (!forbidden[n]) added.emplace_back(n, owner[t]);
  }
  std::vector<unsigned char> isSeed(mesh.tetCount(), 0);
  for (int s : seeds) isSeed[s] = 1;
  for (const auto& [t, o] : added)
    if (isSeed[t]) return false;
  for (const auto& [t, o] : added)
    if (!forbidden[t]) forbidden[t] = 1, owner[t] = o;
  return true;
}

}  // namespace

std::vector<std::string> RemoveCurvesReport::lines() const {
  std::vector<std::string> out;
  std::string head = std::string(toString(scenario)) + " removal of ";
  for (std::size_t i = 0; i < targets.size(); ++i)
    head += (i ? " and " : "") + targets[i] + " (picked " + editNumber(pickDistances[i]) + " away)";
  out.push_back(head);
  for (const std::string& line : reconnection) out.push_back("step 1 (reconnection): " + line);
  if (!reconnection.empty()) out.push_back("step 2: one-loop removal of the merged loop");
  out.push_back("region: " + std::to_string(regionTets) + " tets, " +
                std::to_string(regionVertices) + " vertices (" + std::to_string(freeVertices) +
                " free, " + std::to_string(heldVertices) + " held; " +
                std::to_string(freeOnSurface) + " free on the domain surface, " +
                std::to_string(surfaceFaces) + " boundary faces on it)");
  out.push_back("region growth: " + growStop + "; shrink: " + shrinkStop +
                "; grow out: " + growOutStop);
  std::string flowLine = flow.summary() + "; " + std::to_string(signConflicts) + " sign conflicts";
  if (conflictRegrowths > 0)
    flowLine += " (region grown again " + std::to_string(conflictRegrowths) + " times around " +
                std::to_string(conflictEdges) + " conflicting edges)";
  if (defectRegrowths > 0)
    flowLine += "; region grown again " + std::to_string(defectRegrowths) + " times around " +
                std::to_string(defectFaces) +
                " boundary faces where the medium eigenvector turns by half a turn";
  out.push_back(flowLine);
  std::string t = "tries: " + std::to_string(tries.size());
  if (widenings > 0)
    t += " (" + std::to_string(widenings) + " with one more ring of tets kept from other curves)";
  t += describeTries(tries);
  out.push_back(t);
  addEditClosingLines(out, seconds, curvesBefore, curvesAfter);
  return out;
}

RemoveCurvesResult removeCurves(const TensorField& field, const RemoveCurvesOptions& o,
                                const Progress& progress) {
  const SmallPagesScope smallPages;  // an edit's arrays live for one cook (core/small_pages.h)
  const auto start = std::chrono::steady_clock::now();
  const TetMesh& mesh = field.mesh();
  const EditRetries plan = editRetries(mesh, o.regionDistance, o.retries, o.growFactor);
  progress.report(0, "extracting curves");
  std::optional<DegenerateCurves> extracted;
  if (!o.extracted) extracted = extractDegenerateCurves(field, o.extract, progress);
  const DegenerateCurves& all = o.extracted ? *o.extracted : *extracted;
  const Targets targets = resolveTargets(mesh, all, o);
  RemoveCurvesReport report;
  report.scenario = removalScenario(targets.curves);
  for (const DegenerateCurve* c : targets.curves) report.targets.push_back(describeCurve(*c));
  report.pickDistances = targets.pickDistances;
  report.curvesBefore = all.size();
  if (report.scenario == RemovalScenario::TwoLoop)
    return removeTwoLoops(field, o, all, *targets.curves[0], *targets.curves[1], std::move(report),
                          progress);
  const DegenerateType type = targets.curves[0]->type;

  ForbiddenTets forbid = forbidOtherCurves(mesh, all, targets.ids);
  std::vector<unsigned char>& forbidden = forbid.flag;
  std::vector<int>& owner = forbid.owner;
  const std::vector<int> seeds = seedTets(mesh, targets);
  const std::vector<int> ownTets = targetTets(mesh, targets);
  const std::vector<unsigned char> isSeed = tetFlags(mesh, seeds);
  for (int s : seeds)
    if (forbidden[s]) refuseCut(mesh, all, targets, type, owner[s]);

  std::optional<RemoveCurvesResult> result;
  auto attemptTry = [&](int k, RemovalTry& attempt) {
    // After a failed re-extraction (a new curve or a piece of a target in the region), the
    // retry also keeps one more ring of tets away from the other curves: next to them the held
    // eigenvalue gaps are small and the new field turns fast across the tets there, where the
    // linear interpolation of a face can hold a degenerate point although every vertex has
    // positive gaps.
    if (k > 0 && (report.tries.back().failedCheck == "nothing new in the region" ||
                  report.tries.back().failedCheck == "targets gone")) {
      if (widenAroundCurves(mesh, seeds, forbidden, owner)) ++report.widenings;
    }
    const BallRegion region = growBallRegion(mesh, seeds, forbidden, {attempt.distance}, progress);
    if (!region.complete) {
      if (region.blockingTet >= 0) refuseCut(mesh, all, targets, type, owner[region.blockingTet]);
      throw RemovalRefused("no ball region around the targets: " + region.growStop);
    }
    attempt.regionTets = region.tets.size();
    const RegionExamination x = examineRegion(field, region.tets, type);
    const RegionVertices& rv = x.vertices;
    std::optional<TensorField> edited;
    if (!x.ball.ball) {
      attempt.failedCheck = "region is a ball", attempt.detail = x.ball.problem;
    } else if (rv.free.size() == rv.vertices.size()) {
      attempt.failedCheck = "region leaves a held boundary";
      attempt.detail = "the region grew to the whole mesh: nothing outside it holds the field";
    } else {
      x.throwIfFailed();
      const RegionComplex& complex = *x.complex;
      const VectorisedEigenvector& vec = *x.vec;
      if (vec.signConflicts > 0 && report.conflictRegrowths < kConflictRegrowths) {
        // §6.1: the region holds no degenerate point but the targets'. A sign conflict marks
        // one of the other type (where the non-repeating eigenvector repeats) that no extracted
        // curve covers: the tets around the conflicting edges are forbidden like another
        // curve's, and this try grows its region again.
        for (int e : vec.conflictEdges)
          for (int v : mesh.edges()[e])
            for (int n : mesh.vertexTets(v)) forbid.add(n, conflictOwner(e));
        for (int s : seeds)
          if (forbidden[s]) refuseCut(mesh, all, targets, type, owner[s]);
        ++report.conflictRegrowths;
        report.conflictEdges += vec.signConflicts;
        return TryOutcome::Again;
      }
      const AngleDefects defects = angleDefects(field, complex, vec, rv.held, ownTets);
      if (!defects.faces.empty() && report.defectRegrowths < kDefectRegrowths) {
        // §6.3 needs held values of the angle θ that lift continuously (Equation 5): a
        // degenerate point of the targets' type on the held boundary, or a surface patch around
        // which the medium eigenvector winds, would leave a seam from which the solved θ has a
        // singular line. The tets around those faces are forbidden and the region grows again,
        // unless that would take a seed (the region must hold the seeds: such a defect is left
        // to the verification, as before this check).
        std::vector<std::pair<int, int>> added;  // (tet, face)
        for (int f : defects.faces)
          for (int v : mesh.faces()[f])
            for (int n : mesh.vertexTets(v))
              if (!forbidden[n]) added.emplace_back(n, f);
        const bool takesSeed = std::any_of(added.begin(), added.end(),
                                           [&](const auto& a) { return isSeed[a.first] != 0; });
        if (!added.empty() && !takesSeed) {
          for (const auto& [t, f] : added) forbid.add(t, defectOwner(mesh, f));
          ++report.defectRegrowths;
          report.defectFaces += static_cast<int>(defects.faces.size());
          return TryOutcome::Again;
        }
      }
      report.flow = boundaryFlow(mesh, region.tets, vec);
      report.signConflicts = vec.signConflicts;
      try {
        edited = singularityFreeField(field, complex, vec, rv.held, type, progress, nullptr,
                                      /*smoothEveryFastTurn=*/true);
      } catch (const Cancelled&) {
        throw;
      } catch (const Error& e) {
        attempt.failedCheck = "singularity-free field", attempt.detail = e.what();
      }
    }
    if (!attempt.failedCheck.empty()) return TryOutcome::Failed;
    DegenerateCurves after = extractDegenerateCurves(*edited, o.extract, progress);
    const EditVerification v =
        verifyEdit(field, *edited, rv.free, region.tets, all, after, targets.ids);
    attempt.failedCheck = v.failedCheck, attempt.detail = v.detail;
    if (!v.passed) return TryOutcome::Failed;
    report.regionTets = region.tets.size();
    report.regionVertices = rv.vertices.size();
    report.freeVertices = rv.free.size();
    report.heldVertices = rv.vertices.size() - rv.free.size();
    report.freeOnSurface = rv.freeOnSurface;
    report.surfaceFaces = rv.surfaceFaces;
    report.growStop = region.growStop, report.shrinkStop = region.shrinkStop;
    report.growOutStop = region.growOutStop;
    report.curvesAfter = after.size();
    result = RemoveCurvesResult{std::move(*edited), std::move(after), region.tets, {}};
    return TryOutcome::Verified;
  };
  if (!runEditTries(plan, report.tries, progress, attemptTry))
    failAfterTries<RemovalFailed>("verification", report.tries);
  report.seconds = secondsSince(start);
  result->report = std::move(report);
  progress.report(1, "verified");
  return std::move(*result);
}

}  // namespace tfd::core
