// Degenerate curve reconnection (paper §6.2; core/edit/reconnect_curves.h) on fields whose
// curves are known exactly (removal_test_fields.h: degenerate where W = f + i g = 0, wedge where
// (∇f × ∇g) · e > 0). A product W = W1 · W2 has the two curves of its factors with their own
// patterns. The scenarios of Fig. 11, with e (so V) pointing up (+z, slightly tilted):
//  a→  a pure wedge and a pure trisector line            -> two mixed curves (cap and cup)
//  a←  a mixed cap (both ends down) and a mixed cup      -> a wedge and a trisector line
//  b   two pure wedge lines                              -> two wedge lines, ends swapped
//  c   two pure trisector lines                          -> two trisector lines, ends swapped
//  d   a pure wedge line and a mixed cap                 -> a mixed cap and a wedge curve
//  e   two mixed caps side by side (all ends incoming)   -> an outer and an inner cap
// For each, the pairing Theorem 6.2 gives was worked out by hand from the geometry (which leg
// joins which) and is checked against the edit's pairing; the ends' patterns against the
// analytic sign of (∇f × ∇g) · e; the new curves against the pairing by an independent search
// of the returned curves; everything outside the region against the input, bitwise.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <functional>

#include "core/derived_cache.h"
#include "core/edit/reconnect_curves.h"
#include "core/edit/reconnect_field.h"
#include "core/edit/reconnect_sheet.h"
#include "core/edit/region_complex.h"
#include "core/region/ball_check.h"
#include "core/region/region_vertices.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/reconnect_test_fields.h"
#include "tests/core/edit/removal_test_fields.h"

namespace tfd::core {
namespace {

using testing::Complex;

std::shared_ptr<const TetMesh> box() {
  static const auto mesh = testing::jitteredBox(18, 0.15);
  return mesh;
}

using testing::Scenario;
using testing::scenarios;
using testing::upFrame;

bool bitwiseEqual(const Tensor& a, const Tensor& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Wedge or trisector at a point of W = 0 from the analytic sign of (∇f × ∇g) · e.
DegeneratePattern analyticPattern(const std::function<Complex(const Vec3&)>& W, const Vec3& p) {
  const double d = 1e-6;
  Vec3 gf, gg;
  for (int i = 0; i < 3; ++i) {
    Vec3 h = Vec3::Zero();
    h[i] = d;
    const Complex dw = (W(p + h) - W(p - h)) / (2 * d);
    gf[i] = dw.real(), gg[i] = dw.imag();
  }
  return gf.cross(gg).dot(upFrame().e) > 0 ? DegeneratePattern::Wedge
                                           : DegeneratePattern::Trisector;
}

/// testing::sameCurveHolds on the box by default.
bool sameCurveHolds(const DegenerateCurves& curves, const Vec3& a, const Vec3& b,
                    const TetMesh& mesh = *box()) {
  return testing::sameCurveHolds(curves, a, b, mesh);
}

ReconnectCurvesOptions options(const Scenario& s) {
  ReconnectCurvesOptions o;
  o.picks = {s.picks[0], s.picks[1]};
  o.regionDistance = 0.3;
  return o;
}

void expectReconnected(const Scenario& s, const std::shared_ptr<const TetMesh>& mesh = box(),
                       double segmentLength = -1) {
  SCOPED_TRACE(s.name);
  const TensorField field =
      testing::designedField(mesh, s.W, [](const Vec3&) { return upFrame(); });
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 2u) << before.summary();
  ReconnectCurvesOptions o = options(s);
  o.segmentLength = segmentLength;
  const ReconnectCurvesResult r = reconnectCurves(field, o);
  const ReconnectCurvesReport& rep = r.report;
  for (const std::string& line : rep.lines()) std::printf("  %s\n", line.c_str());
  // Theorem 6.2's pairing, worked out by hand from the geometry.
  for (int i = 0; i < 2; ++i) {
    const int j = rep.partner[i];
    ASSERT_GE(j, 2);
    EXPECT_EQ(rep.partner[j], i);
    EXPECT_TRUE(s.joins(rep.ends[i].position, rep.ends[j].position))
        << "end " << i << " joined to " << j;
  }
  // The ends' patterns are the analytic ones; Lemma 6.1 holds on the original segments.
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(rep.ends[i].pattern, analyticPattern(s.W, rep.ends[i].position)) << "end " << i;
  EXPECT_NE(rep.ends[0].charge(), rep.ends[1].charge());
  EXPECT_NE(rep.ends[2].charge(), rep.ends[3].charge());
  // The new curves join the paired ends (searched independently in the returned curves), and
  // the returned curves are the field's.
  for (int i = 0; i < 2; ++i)
    EXPECT_TRUE(
        sameCurveHolds(r.curves, rep.ends[i].position, rep.ends[rep.partner[i]].position, *mesh))
        << "end " << i;
  EXPECT_FALSE(sameCurveHolds(r.curves, rep.ends[0].position, rep.ends[1].position, *mesh) &&
               sameCurveHolds(r.curves, rep.ends[2].position, rep.ends[3].position, *mesh))
      << "the old connection is still there";
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), r.curves.size());
  // The region is a ball; outside its free vertices nothing changed bitwise.
  const BallCheck ball = checkTopologicalBall(*mesh, r.regionTets);
  EXPECT_TRUE(ball.ball) << ball.problem;
  const RegionVertices rv = regionVertices(*mesh, r.regionTets);
  std::vector<char> isFree(mesh->vertexCount(), 0);
  for (int v : rv.free) isFree[v] = 1;
  int changed = 0;
  for (int v = 0; v < int(mesh->vertexCount()); ++v) {
    if (isFree[v])
      changed += !bitwiseEqual(field.at(v), r.field.at(v));
    else
      ASSERT_TRUE(bitwiseEqual(field.at(v), r.field.at(v))) << "vertex " << v;
  }
  EXPECT_GT(changed, 0);
}

TEST(ReconnectCurves, CaseAWedgeAndTrisectorBecomeTwoMixedCurves) {
  expectReconnected(scenarios()[0]);
}
TEST(ReconnectCurves, CaseATwoMixedCurvesBecomeAWedgeAndATrisector) {
  expectReconnected(scenarios()[1]);
}
TEST(ReconnectCurves, CaseBTwoWedgesSwapEnds) { expectReconnected(scenarios()[2]); }
TEST(ReconnectCurves, CaseCTwoTrisectorsSwapEnds) { expectReconnected(scenarios()[3]); }
TEST(ReconnectCurves, CaseDAWedgeAndAMixedCurve) { expectReconnected(scenarios()[4]); }
TEST(ReconnectCurves, CaseETwoMixedCurvesOnOneSide) { expectReconnected(scenarios()[5]); }

TEST(ReconnectCurves, EveryScenarioOnACarvedBall) {
  // The same six scenarios on a second solid: a ball carved from a jittered box (its surface
  // cuts the curves, which end there; the region keeps away from those ends).
  static const auto ball = testing::carvedBall(18);
  for (const Scenario& s : scenarios()) expectReconnected(s, ball);
}

TEST(ReconnectCurves, BreaksAMixedLoopInTwo) {
  // The circle x² + z² = 0.36, y = 0: with e up, its right half is a wedge and its left half a
  // trisector (transitions at the top and bottom). Reconnecting its right and left sides joins
  // the two lower ends and the two upper ends (case a): one loop becomes two.
  const auto mesh = box();
  auto W = [](const Vec3& p) { return Complex(p.x() * p.x() + p.z() * p.z() - 0.36, p.y()); };
  const TensorField field = testing::designedField(mesh, W, [](const Vec3&) { return upFrame(); });
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 1u) << before.summary();
  ASSERT_TRUE(before.curve(0).closed);
  ReconnectCurvesOptions o;
  o.picks = {Vec3(0.6, 0, 0), Vec3(-0.6, 0, 0)};
  o.segmentLength = 0.5;
  o.regionDistance = 0.3;
  const ReconnectCurvesResult r = reconnectCurves(field, o);
  for (const std::string& line : r.report.lines()) std::printf("  %s\n", line.c_str());
  ASSERT_EQ(r.curves.size(), 2u) << r.curves.summary();
  EXPECT_TRUE(r.curves.curve(0).closed);
  EXPECT_TRUE(r.curves.curve(1).closed);
  for (int i = 0; i < 2; ++i) {
    const int j = r.report.partner[i];
    EXPECT_EQ(r.report.ends[i].position.z() > 0, r.report.ends[j].position.z() > 0);
    EXPECT_TRUE(sameCurveHolds(r.curves, r.report.ends[i].position, r.report.ends[j].position));
  }
  EXPECT_NE(r.report.lines().back().find("1 curves -> 2"), std::string::npos);
}

TEST(ReconnectCurves, TheOtherPairingIsNotARealisableReconnection) {
  // Lemma 6.1 in the other direction: joining the ends the theorem does not pair would need a
  // curve with an even number of transitions between ends in the same part (or an odd number
  // between parts). Every scenario's ends confirm that exactly one pairing is allowed.
  for (const Scenario& s : scenarios()) {
    SCOPED_TRACE(s.name);
    const TensorField field =
        testing::designedField(box(), s.W, [](const Vec3&) { return upFrame(); });
    const ReconnectCurvesResult r = reconnectCurves(field, options(s));
    const auto& e = r.report.ends;
    const int j = r.report.partner[0], other = j == 2 ? 3 : 2;
    EXPECT_TRUE(lemmaAllowsJoin(e[0], e[j]));
    EXPECT_FALSE(lemmaAllowsJoin(e[0], e[other]));
    EXPECT_TRUE(lemmaAllowsJoin(e[1], e[other]));
    // The boundary faces' own classification agrees with the curves' here (curves cross the
    // region's boundary roughly along V).
    for (int i = 0; i < 4; ++i)
      if (e[i].faceIncoming >= 0) {
        EXPECT_EQ(e[i].faceIncoming, int(e[i].incoming)) << i;
      }
  }
}

TEST(ReconnectCurves, ASheetBetweenTheOtherPairsDoesNotJoinThem) {
  // Falsification of Theorem 6.2 by construction: the same steps 3–5 with the sheet built for
  // the pairing the theorem rules out (A with the other end of the second segment). Around the
  // sheet's held rim the medium eigenvector then turns once (the two old curves pierce the
  // sheet the same way), so no field without degenerate points exists on the sheet and the
  // re-extracted curves do not join the ends that way.
  const auto mesh = box();
  int built = 0;
  for (const Scenario& s : scenarios()) {
    SCOPED_TRACE(s.name);
    const TensorField field =
        testing::designedField(mesh, s.W, [](const Vec3&) { return upFrame(); });
    const DegenerateCurves before = extractDegenerateCurves(field);
    const ReconnectCurvesResult r = reconnectCurves(field, options(s));
    const auto& e = r.report.ends;
    const int wrong = r.report.partner[0] == 2 ? 3 : 2, wrongB = wrong == 2 ? 3 : 2;
    const RegionComplex complex = regionComplex(*mesh, r.regionTets);
    auto end = [&](int i) {
      return SheetEnd{e[i].position, before.curve(e[i].curveId).sources[e[i].pointIndex]};
    };
    const ReconnectSheet sheet =
        reconnectSheet(*mesh, complex, {{{end(0), end(wrong)}, {end(1), end(wrongB)}}});
    if (!sheet.problem.empty()) continue;  // no sheet: not realisable either
    RegionVertices rv = regionVertices(*mesh, r.regionTets);
    for (int v : rv.vertices)
      if (mesh->isBoundaryVertex(v)) rv.held[v] = 1;
    std::erase_if(rv.free, [&](int v) { return mesh->isBoundaryVertex(v); });
    ReconnectFieldReport fr;
    TensorField edited = field;
    try {
      edited = reconnectField(field, sheet.tets, rv, before.curve(e[0].curveId).type, {}, fr);
    } catch (const Error&) {
      continue;  // refused: not realisable
    }
    const DegenerateCurves after = extractDegenerateCurves(edited);
    ++built;
    std::printf("  %s: the ruled-out sheet leaves %zu curves (%s)\n", s.name, after.size(),
                after.summary().c_str());
    EXPECT_FALSE(sameCurveHolds(after, e[0].position, e[wrong].position) &&
                 sameCurveHolds(after, e[1].position, e[wrongB].position))
        << "the ruled-out pairing was realised";
  }
  EXPECT_GE(built, 4) << "the wrong sheet was refused too often to test anything";
}

TEST(ReconnectCurves, PairingFollowsTheCharges) {
  // Theorem 6.2 by table: all sixteen charge patterns of the four ends that satisfy Lemma 6.1
  // on the two segments give the partner with the other charge; the others are refused.
  for (int bits = 0; bits < 16; ++bits) {
    std::array<ReconnectEndpoint, 4> e;
    for (int i = 0; i < 4; ++i) {
      e[i].segment = i / 2;
      e[i].incoming = (bits >> i) & 1;
      e[i].pattern = i % 3 == 0 ? DegeneratePattern::Wedge : DegeneratePattern::Trisector;
    }
    const ReconnectPairing p = pairEndpoints(e);
    const bool lemma = e[0].charge() != e[1].charge() && e[2].charge() != e[3].charge();
    EXPECT_EQ(p.consistent, lemma) << bits;
    if (!lemma) {
      EXPECT_FALSE(p.problem.empty());
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(p.partner[p.partner[i]], i);
      EXPECT_NE(e[i].segment, e[p.partner[i]].segment);
      EXPECT_NE(e[i].charge(), e[p.partner[i]].charge());
    }
  }
}

TEST(ReconnectCurves, GraphPartitionAgreesWithTheEuclideanOne) {
  // The sheet's nearest-path partition by graph distance against exact Euclidean distances to
  // the same paths (reconnect_sheet.h: why graph distance).
  for (const Scenario& s : scenarios()) {
    SCOPED_TRACE(s.name);
    const auto mesh = box();
    const TensorField field =
        testing::designedField(mesh, s.W, [](const Vec3&) { return upFrame(); });
    const DegenerateCurves before = extractDegenerateCurves(field);
    const ReconnectCurvesResult r = reconnectCurves(field, options(s));
    const RegionComplex complex = regionComplex(*mesh, r.regionTets);
    auto end = [&](int i) {
      const ReconnectEndpoint& e = r.report.ends[i];
      return SheetEnd{e.position, before.curve(e.curveId).sources[e.pointIndex]};
    };
    const ReconnectSheet sheet = reconnectSheet(
        *mesh, complex, {{{end(0), end(r.report.partner[0])}, {end(1), end(r.report.partner[1])}}});
    ASSERT_TRUE(sheet.problem.empty()) << sheet.problem;
    EXPECT_EQ(sheet.tets.size(), r.report.sheetTets);
    const std::vector<signed char> exact = euclideanLabels(*mesh, complex, sheet.paths);
    std::vector<char> onSheet(mesh->vertexCount(), 0);
    for (int t : sheet.tets)
      for (int v : mesh->tets()[t]) onSheet[v] = 1;
    std::size_t same = 0, differentOnSheet = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
      same += exact[i] == sheet.label[i];
      differentOnSheet += exact[i] != sheet.label[i] && onSheet[complex.vertices[i]];
    }
    const double agreement = double(same) / double(exact.size());
    const std::size_t different = exact.size() - same;
    std::printf(
        "  %s: graph and Euclidean labels agree on %.1f %% of %zu vertices; %zu of the %zu "
        "others are sheet vertices\n",
        s.name, 100 * agreement, exact.size(), differentOnSheet, different);
    EXPECT_GE(agreement, 0.9);
  }
}

TEST(ReconnectCurves, BadInputIsAClearError) {
  const auto mesh = box();
  const Scenario& s = scenarios()[0];
  const TensorField field =
      testing::designedField(mesh, s.W, [](const Vec3&) { return upFrame(); });
  auto message = [&](const ReconnectCurvesOptions& o) -> std::string {
    try {
      reconnectCurves(field, o);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  ReconnectCurvesOptions o = options(s);
  o.picks.pop_back();
  EXPECT_NE(message(o).find("picks: give two points"), std::string::npos);
  o = options(s);
  o.picks[1] = Vec3(0, std::nan(""), 0);
  EXPECT_NE(message(o).find("not a finite point"), std::string::npos);
  o = options(s);
  o.segmentLength = 0;
  EXPECT_NE(message(o).find("segment_length"), std::string::npos);
  o = options(s);
  o.picks[1] = Vec3(0.3, 0, 0.05);  // the same segment twice
  EXPECT_NE(message(o).find("same segment"), std::string::npos) << message(o);
  o = options(s);
  o.picks[0] = Vec3(0.3, 0, 0.9);  // 0.1 from where the line ends on the box's top face
  EXPECT_NE(message(o).find("ends on the domain surface"), std::string::npos) << message(o);
  o = options(s);
  o.retries = -1;
  EXPECT_NE(message(o).find("retries"), std::string::npos);
  const TensorField flat = testing::designedField(mesh, [](const Vec3&) { return Complex(1, 0); });
  try {
    reconnectCurves(flat, options(s));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no degenerate curves"), std::string::npos);
  }
}

TEST(ReconnectCurves, OneAndTwoThreadsGiveTheSameBits) {
  const Scenario& s = scenarios()[2];  // b: the rerouted path
  const TensorField field =
      testing::designedField(box(), s.W, [](const Vec3&) { return upFrame(); });
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    derivedCache().clear();  // each run builds its own solver set-up
    return reconnectCurves(field, options(s));
  };
  const ReconnectCurvesResult a = run(1), b = run(2);
  EXPECT_EQ(a.regionTets, b.regionTets);
  for (int v = 0; v < int(box()->vertexCount()); ++v)
    ASSERT_TRUE(bitwiseEqual(a.field.at(v), b.field.at(v))) << v;
  EXPECT_EQ(a.curves.size(), b.curves.size());
}

}  // namespace
}  // namespace tfd::core
