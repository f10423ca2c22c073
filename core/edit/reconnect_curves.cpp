#include "core/edit/reconnect_curves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "core/edit/edit_driver.h"
#include "core/edit/reconnect_field.h"
#include "core/edit/reconnect_segments.h"
#include "core/edit/reconnect_sheet.h"
#include "core/edit/reconnect_verification.h"
#include "core/edit/region_complex.h"
#include "core/edit/region_examination.h"
#include "core/edit/removal_scenario.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/region/region_vertices.h"
#include "core/small_pages.h"
#include "core/topology/curve_tets.h"

namespace tfd::core {
namespace {

/// Arc-length distance of every point of the curve from the picked position (along the curve,
/// either way round a loop).
std::vector<double> arcDistances(const DegenerateCurve& c, const CurvePick& pick) {
  const std::size_t n = c.points.size();
  std::vector<double> s(n, 0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + (c.points[i] - c.points[i - 1]).norm();
  const double total = c.closed && n > 1 ? s[n - 1] + (c.points[0] - c.points[n - 1]).norm() : 0;
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = std::abs(s[i] - pick.arcLength);
    if (c.closed) d[i] = std::min(d[i], total - d[i]);
  }
  return d;
}

/// Regrowths of the region around sign conflicts per segment length (as for removal).
constexpr int kConflictRegrowths = 8;

/// Segment lengths tried after the asked one, as factors of it (reconnectCurves).
constexpr double kSegmentFactors[] = {0.6, 1.5};

std::string endText(const ReconnectEndpoint& e) {
  return std::string(toString(e.pattern)) + ", " + (e.incoming ? "incoming" : "outgoing") +
         " (V·t " + editNumber(e.alignment) + "; boundary face: " +
         (e.faceIncoming < 0 ? "n/a"
          : e.faceIncoming   ? "incoming"
                             : "outgoing") +
         "; charge " + std::to_string(e.charge()) +
         (e.ownAgrees() ? "" : ", voted along the segment against the end's own") + ") at (" +
         editNumber(e.position.x()) + ", " + editNumber(e.position.y()) + ", " +
         editNumber(e.position.z()) + ")";
}

/// The region's vertices on the domain surface held too: the new curves must join the ends
/// inside the region, not end on the surface (the paper's local smoothing holds R ∩ ∂M alike).
RegionVertices heldOnSurface(const TetMesh& mesh, RegionVertices rv) {
  std::vector<int> free;
  for (int v : rv.free) {
    if (mesh.isBoundaryVertex(v))
      rv.held[v] = 1;
    else
      free.push_back(v);
  }
  rv.free = std::move(free);
  rv.freeOnSurface = 0;
  return rv;
}

/// The segments of one length have no valid setup: they reach a picked curve's end on the
/// domain surface, or another curve passes next to them.
class NoValidSegment : public Error {
 public:
  using Error::Error;
};

struct Setup {
  std::array<CurvePick, 2> picks;
  std::vector<int> targetIds;  ///< distinct
  std::vector<int> seeds;
  ForbiddenTets forbid;
};

Setup setUp(const TetMesh& mesh, const DegenerateCurves& all, const ReconnectCurvesOptions& o,
            double& segmentLength) {
  if (o.picks.size() != 2)
    throw Error("picks: give two points, one on each segment (got " +
                std::to_string(o.picks.size()) + ")");
  if (all.empty()) throw Error("the field has no degenerate curves to reconnect");
  Setup s;
  for (int k = 0; k < 2; ++k) {
    if (!o.picks[k].allFinite()) throw Error("picks: a pick is not a finite point");
    s.picks[k] = resolveCurvePick(mesh, all, o.curves, o.picks[k]);
  }
  const DegenerateCurve &c0 = all.curve(s.picks[0].curveId), &c1 = all.curve(s.picks[1].curveId);
  if (c0.type != c1.type)
    throw Error("picks: " + describeCurve(c0) + " and " + describeCurve(c1) +
                " are of different L/P types; a reconnection joins curves of one type");
  const double h = mesh.meanEdgeLength();
  if (!std::isfinite(o.segmentLength) || o.segmentLength == 0)
    throw Error("segment_length: give a positive length, or a negative value for the default");
  segmentLength = o.segmentLength > 0
                      ? o.segmentLength
                      : std::max(4 * h, (s.picks[0].position - s.picks[1].position).norm());
  s.targetIds = {c0.id};
  if (c1.id != c0.id) s.targetIds.push_back(c1.id);
  s.forbid = forbidOtherCurves(mesh, all, s.targetIds);
  // The segments seed the region; the picked curves beyond them (and a margin) are forbidden,
  // except where their tets are seeds (next to the segments' ends, where the region's boundary
  // will cut the curve).
  std::vector<int> core;
  std::vector<std::vector<int>> far(s.targetIds.size());
  for (std::size_t k = 0; k < s.targetIds.size(); ++k) {
    const DegenerateCurve& c = all.curve(s.targetIds[k]);
    std::vector<double> d(c.points.size(), std::numeric_limits<double>::infinity());
    for (int q = 0; q < 2; ++q) {
      if (s.picks[q].curveId != c.id) continue;
      const std::vector<double> dq = arcDistances(c, s.picks[q]);
      for (std::size_t i = 0; i < d.size(); ++i) d[i] = std::min(d[i], dq[i]);
      // A segment must leave the region through its held boundary before the curve ends on
      // the domain surface: refused when that end is within the segment (and an edge).
      const double toEnd =
          c.closed ? std::numeric_limits<double>::infinity() : std::min(dq.front(), dq.back());
      if (toEnd <= 0.5 * segmentLength + h)
        throw NoValidSegment("picks: " + describeCurve(c) + " ends on the domain surface " +
                             editNumber(toEnd) +
                             " along the curve from the pick, within half the " + "segment (" +
                             editNumber(0.5 * segmentLength) + ") and an edge length: move " +
                             "the pick or shorten segment_length");
    }
    // A loop must keep a part outside the region, so that the segments have ends: some point
    // beyond the segment and its margin (forbidden below).
    if (c.closed && *std::max_element(d.begin(), d.end()) <= 0.5 * segmentLength + 3 * h)
      throw NoValidSegment("picks: the loop " + describeCurve(c) + " (length " +
                           editNumber(c.length()) + ") is too short for segments of length " +
                           editNumber(segmentLength) + " and a margin of three edge lengths " +
                           "outside them (no valid segment: shorten segment_length)");
    for (std::size_t i = 0; i < d.size(); ++i) {
      const std::vector<int> tets = tetsOfSource(mesh, c.sources[i]);
      if (d[i] <= 0.5 * segmentLength) core.insert(core.end(), tets.begin(), tets.end());
      // An open curve's ends (on the domain surface) are always kept out: a segment must leave
      // the region through its held boundary, not end in it.
      const bool end = !c.closed && (i == 0 || i + 1 == d.size());
      if (end || d[i] > 0.5 * segmentLength + 3 * h)
        far[k].insert(far[k].end(), tets.begin(), tets.end());
    }
  }
  s.seeds = withNeighbourTets(mesh, core);
  // The seeds must keep off an open picked curve's ends on the domain surface: else the segment
  // would end on the surface inside the region, and no region holding the seeds lets it leave
  // through the held boundary.
  std::vector<unsigned char> nearEnd(mesh.tetCount(), 0);
  for (int id : s.targetIds) {
    const DegenerateCurve& c = all.curve(id);
    if (c.closed) continue;
    for (std::size_t i : {std::size_t(0), c.points.size() - 1})
      for (int t : tetsOfSource(mesh, c.sources[i])) nearEnd[t] = 1;
  }
  for (int t : s.seeds)
    if (nearEnd[t])
      throw NoValidSegment("picks: the segments of length " + editNumber(segmentLength) +
                           " around the picks reach where a picked curve ends on the domain "
                           "surface (no valid segment: move the pick or shorten segment_length)");
  for (int t : s.seeds)
    if (s.forbid.flag[t])
      throw NoValidSegment(
          "no ball region holds both segments: " + describeCurve(all.curve(s.forbid.owner[t])) +
          " passes next to them (move the picks or shorten segment_length)");
  std::vector<unsigned char> isSeed(mesh.tetCount(), 0);
  for (int t : s.seeds) isSeed[t] = 1;
  for (std::size_t k = 0; k < far.size(); ++k)
    for (int t : withNeighbourTets(mesh, far[k]))
      if (!isSeed[t]) s.forbid.add(t, s.targetIds[k]);
  return s;
}

}  // namespace

std::vector<std::string> ReconnectCurvesReport::lines() const {
  std::vector<std::string> out;
  out.push_back("reconnection of " + curves[0] + " (picked " + editNumber(pickDistances[0]) +
                " away) and " + curves[1] + " (picked " + editNumber(pickDistances[1]) +
                " away), segments of length " + editNumber(segmentLength));
  for (int i = 0; i < 4; ++i)
    out.push_back(std::string("end ") + endpointName(i) + " (segment " +
                  std::to_string(ends[i].segment + 1) + "): " + endText(ends[i]));
  if (partner[0] >= 0)
    out.push_back(std::string("pairing (Lemma 6.1, Theorem 6.2): A joins ") +
                  endpointName(partner[0]) + ", B joins " + endpointName(partner[1]));
  out.push_back("region: " + std::to_string(regionTets) + " tets, " +
                std::to_string(regionVertices) + " vertices (" + std::to_string(freeVertices) +
                " free, " + std::to_string(heldVertices) + " held); " + flow.summary());
  out.push_back("region growth: " + growStop + "; shrink: " + shrinkStop +
                "; grow out: " + growOutStop);
  out.push_back("sheet (graph shortest paths of " + std::to_string(pathVertices[0]) + " and " +
                std::to_string(pathVertices[1]) + " vertices, lengths " +
                editNumber(pathLengths[0]) + " and " + editNumber(pathLengths[1]) +
                (pathsAdjusted ? ", the second rerouted around the first" : "") +
                "): " + std::to_string(sheetTets) + " tets, " + std::to_string(sheetSolved) +
                " of " + std::to_string(sheetVertices) + " vertices solved; " +
                std::to_string(sidesSolved) + " vertices of the two parts re-solved");
  out.push_back(sheetField.summary());
  out.push_back("new curves: " + newCurves[0] + "; " + newCurves[1]);
  out.push_back("tries: " + std::to_string(tries.size()) + describeTries(tries));
  if (!askedSegmentProblem.empty())
    out.push_back("the asked segments had no valid setup (" + askedSegmentProblem +
                  "); segments of length " + editNumber(segmentLength) + " were used");
  if (!tries.empty() && tries.back().segmentLength != tries.front().segmentLength) {
    std::string lengths = "segment length per try:";
    for (const ReconnectTry& t : tries) lengths += " " + editNumber(t.segmentLength);
    out.push_back(lengths);
  }
  addEditClosingLines(out, seconds, curvesBefore, curvesAfter);
  return out;
}

ReconnectCurvesResult reconnectCurves(const TensorField& field, const ReconnectCurvesOptions& o,
                                      const Progress& progress) {
  const SmallPagesScope smallPages;  // an edit's arrays live for one cook (core/small_pages.h)
  const auto start = std::chrono::steady_clock::now();
  const TetMesh& mesh = field.mesh();
  const EditRetries plan = editRetries(mesh, o.regionDistance, o.retries, o.growFactor);
  progress.report(0, "extracting curves");
  std::optional<DegenerateCurves> extracted;
  if (!o.extracted) extracted = extractDegenerateCurves(field, o.extract, progress);
  const DegenerateCurves& all = o.extracted ? *o.extracted : *extracted;
  ReconnectCurvesReport report;
  // The asked segments; when they have no valid setup, the other lengths below are tried
  // before refusing.
  std::optional<Setup> asked;
  std::string askedProblem;
  try {
    asked = setUp(mesh, all, o, report.segmentLength);
  } catch (const NoValidSegment& e) {
    askedProblem = e.what();
    ReconnectCurvesOptions tiny = o;  // the picks and curves alone (segments of one edge)
    tiny.segmentLength = mesh.meanEdgeLength();
    double ignored = 0;
    try {
      asked = setUp(mesh, all, tiny, ignored);
    } catch (const NoValidSegment&) {
      throw Error(askedProblem);
    }
  }
  Setup* current = &*asked;
  const Setup& s = *asked;  // the picks and curves, the same for every segment length
  const DegenerateType type = all.curve(s.picks[0].curveId).type;
  for (int k = 0; k < 2; ++k) {
    report.curves[k] = describeCurve(all.curve(s.picks[k].curveId));
    report.pickDistances[k] = s.picks[k].distance;
  }
  report.curvesBefore = all.size();
  const std::array<std::array<int, 2>, 2> pickPoints = {
      {{s.picks[0].curveId, s.picks[0].pointIndex}, {s.picks[1].curveId, s.picks[1].pointIndex}}};

  std::optional<ReconnectCurvesResult> result;
  double segmentLength = report.segmentLength;
  int conflictRegrowths = 0;  // of the current segment length
  auto attemptTry = [&](int, ReconnectTry& attempt) {
    attempt.segmentLength = segmentLength;
    const BallRegion region =
        growBallRegion(mesh, current->seeds, current->forbid.flag, {attempt.distance}, progress);
    if (!region.complete) {
      if (region.blockingTet >= 0 && current->forbid.owner[region.blockingTet] >= 0)
        throw Error("no ball region holds both segments without cutting " +
                    describeCurve(all.curve(current->forbid.owner[region.blockingTet])));
      if (region.blockingTet >= 0)
        throw Error(
            "no ball region holds both segments without a degenerate point of the "
            "other type that no extracted curve covers");
      throw Error("no ball region holds both segments: " + region.growStop);
    }
    attempt.regionTets = region.tets.size();
    auto fail = [&](const char* check, std::string detail) {
      attempt.failedCheck = check, attempt.detail = std::move(detail);
      return TryOutcome::Failed;
    };
    const RegionExamination x = examineRegion(field, region.tets, type);
    if (!x.ball.ball) return fail("region is a ball", x.ball.problem);
    const RegionVertices rv = heldOnSurface(mesh, x.vertices);
    x.throwIfFailed();
    const RegionComplex& complex = *x.complex;
    const VectorisedEigenvector& vec = *x.vec;
    if (vec.signConflicts > 0 && conflictRegrowths < kConflictRegrowths) {
      // §6.2 step 1: the region holds no degenerate point but the segments'. A sign conflict
      // marks one of the other type that no extracted curve covers: the tets around the
      // conflicting edges are forbidden like another curve's and the region grows again (as
      // for removal, remove_curves.h), unless that takes a seed.
      bool seedTaken = false;
      std::vector<unsigned char> isSeed(mesh.tetCount(), 0);
      for (int t : current->seeds) isSeed[t] = 1;
      for (int e : vec.conflictEdges)
        for (int v : mesh.edges()[e])
          for (int n : mesh.vertexTets(v)) {
            seedTaken = seedTaken || isSeed[n];
            if (!isSeed[n]) current->forbid.add(n, -2 - e);
          }
      ++conflictRegrowths;
      if (!seedTaken) return TryOutcome::Again;
    }
    if (vec.signConflicts > 0)
      return fail("eigenvector orientable",
                  std::to_string(vec.signConflicts) +
                      " region edges disagree in sign: the region holds a degenerate point of "
                      "the other type");
    report.flow = boundaryFlow(mesh, region.tets, vec);
    const std::vector<unsigned char> inRegion = tetFlags(mesh, region.tets);
    // Step 2: the ends and their pairing.
    const ReconnectSegments segs =
        findReconnectSegments(mesh, all, pickPoints, inRegion, complex, vec);
    if (!segs.problem.empty()) return fail("segments leave the region", segs.problem);
    report.ends = segs.ends;
    const ReconnectPairing pairing = pairEndpoints(segs.ends);
    if (!pairing.consistent) return fail("pairing (Lemma 6.1)", pairing.problem);
    report.partner = pairing.partner;
    // Step 3: the sheet.
    auto sheetEnd = [&](int i) {
      const ReconnectEndpoint& e = segs.ends[i];
      return SheetEnd{e.position, all.curve(e.curveId).sources[e.pointIndex]};
    };
    const int a = 0, c = pairing.partner[0], b = 1, d = pairing.partner[1];
    const ReconnectSheet sheet =
        reconnectSheet(mesh, complex, {{{sheetEnd(a), sheetEnd(c)}, {sheetEnd(b), sheetEnd(d)}}});
    if (!sheet.problem.empty()) return fail("sheet", sheet.problem);
    attempt.sheetTets = sheet.tets.size();
    // Steps 4–5: the field.
    ReconnectFieldReport fr;
    std::optional<TensorField> edited;
    try {
      edited = reconnectField(field, sheet.tets, rv, type, progress, fr);
    } catch (const Cancelled&) {
      throw;
    } catch (const Error& e) {
      return fail("sheet field", e.what());
    }
    DegenerateCurves after = extractDegenerateCurves(*edited, o.extract, progress);
    const ReconnectVerification v = verifyReconnection(
        field, *edited, rv.free, region.tets, all, after, s.targetIds, segs.ends, pairing.partner);
    if (!v.result.passed) return fail(v.result.failedCheck.c_str(), v.result.detail);
    report.regionTets = region.tets.size(), report.regionVertices = rv.vertices.size();
    report.freeVertices = rv.free.size();
    report.heldVertices = rv.vertices.size() - rv.free.size();
    report.growStop = region.growStop, report.shrinkStop = region.shrinkStop;
    report.growOutStop = region.growOutStop;
    for (int k = 0; k < 2; ++k) {
      report.pathVertices[k] = sheet.paths[k].size();
      report.pathLengths[k] = sheet.pathLengths[k];
      report.newCurves[k] = describeCurve(after.curve(v.newCurves[k])) + " joins " +
                            endpointName(v.joins[k][0]) + " and " + endpointName(v.joins[k][1]);
    }
    report.pathsAdjusted = sheet.adjusted;
    report.sheetTets = sheet.tets.size(), report.sheetVertices = fr.sheetVertices;
    report.sheetSolved = fr.sheetSolved, report.sidesSolved = fr.sidesSolved;
    report.sheetField = fr.sheet;
    report.curvesAfter = after.size();
    result = ReconnectCurvesResult{std::move(*edited), std::move(after), region.tets, {}};
    return TryOutcome::Verified;
  };
  // The asked segments first, over the growing regions; when no try verified, shorter and then
  // longer segments (their ends, where the new curves start, move along the curves: away from a
  // place where the re-solved field folds a loop or a path pairs badly), each over the same
  // regions. A segment length without a valid setup (it reaches a curve's end or another curve)
  // is skipped; for the asked one that is the refusal.
  bool verified = askedProblem.empty() && runEditTries(plan, report.tries, progress, attemptTry);
  for (const double factor : kSegmentFactors) {
    if (verified) break;
    segmentLength = factor * report.segmentLength;
    if (segmentLength < 2 * mesh.meanEdgeLength()) continue;
    ReconnectCurvesOptions variant = o;
    variant.segmentLength = segmentLength;
    std::optional<Setup> other;
    try {
      double ignored = 0;
      other = setUp(mesh, all, variant, ignored);
    } catch (const Error&) {
      continue;
    }
    current = &*other;
    conflictRegrowths = 0;
    std::vector<ReconnectTry> tries;
    try {
      verified = runEditTries(plan, tries, progress, attemptTry);
    } catch (const Cancelled&) {
      throw;
    } catch (const Error&) {  // no region for this segment length
    }
    report.tries.insert(report.tries.end(), tries.begin(), tries.end());
    if (verified) report.segmentLength = segmentLength;
  }
  if (!verified && report.tries.empty()) throw Error(askedProblem);  // no length had a setup
  if (!verified) failAfterTries<ReconnectionFailed>("reconnection", report.tries);
  report.askedSegmentProblem = askedProblem;
  report.seconds = secondsSince(start);
  result->report = std::move(report);
  progress.report(1, "verified");
  return std::move(*result);
}

}  // namespace tfd::core
