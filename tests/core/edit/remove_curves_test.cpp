// Degenerate curve removal (paper §6.4; core/edit/remove_curves.h) on fields whose curves are
// known exactly (removal_test_fields.h): each scenario on a box and on a ball, refusals,
// verification, and 1 vs 2 threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

#include "core/derived_cache.h"
#include "core/edit/remove_curves.h"
#include "core/region/ball_check.h"
#include "core/region/region_vertices.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/removal_test_fields.h"

namespace tfd::core {
namespace {

using testing::Complex;

struct Scenario {
  const char* name;
  Complex (*W)(const Vec3&);
  std::vector<Vec3> picks;
  RemovalScenario expected;
  int removed;
};

Complex loop(const Vec3& p) { return testing::loopW(p); }
Complex arc(const Vec3& p) { return testing::arcW(p); }
Complex lines(const Vec3& p) { return testing::twoLinesW(p); }

const Scenario kScenarios[] = {
    {"one-loop", loop, {Vec3(0.4, 0, 0)}, RemovalScenario::OneLoop, 1},
    {"one-curve", arc, {Vec3(0, 0, 0.3)}, RemovalScenario::OneCurve, 1},
    {"two-curve", lines, {Vec3(-0.3, 0, 0), Vec3(0.3, 0, 0.1)}, RemovalScenario::TwoCurve, 2},
};

bool bitwiseEqual(const Tensor& a, const Tensor& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectRemoved(const std::shared_ptr<const TetMesh>& mesh, const Scenario& s) {
  SCOPED_TRACE(s.name);
  const TensorField field = testing::designedField(mesh, s.W);
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_GE(before.size(), std::size_t(s.removed)) << before.summary();
  RemoveCurvesOptions o;
  o.picks = s.picks;
  const RemoveCurvesResult r = removeCurves(field, o);
  EXPECT_EQ(r.report.scenario, s.expected);
  ASSERT_FALSE(r.report.tries.empty());
  EXPECT_TRUE(r.report.tries.back().failedCheck.empty());
  EXPECT_EQ(r.curves.size(), before.size() - s.removed) << r.curves.summary();
  EXPECT_EQ(r.report.curvesBefore, before.size());
  EXPECT_EQ(r.report.curvesAfter, r.curves.size());
  // Independent checks: the region is a ball; outside its free vertices nothing changed
  // bitwise; the re-extraction of the returned field is the returned curve set.
  const BallCheck ball = checkTopologicalBall(*mesh, r.regionTets);
  EXPECT_TRUE(ball.ball) << ball.problem;
  const RegionVertices rv = regionVertices(*mesh, r.regionTets);
  std::vector<char> isFree(mesh->vertexCount(), 0);
  for (int v : rv.free) isFree[v] = 1;
  int changedInside = 0;
  for (int v = 0; v < int(mesh->vertexCount()); ++v) {
    if (isFree[v])
      changedInside += !bitwiseEqual(field.at(v), r.field.at(v));
    else
      ASSERT_TRUE(bitwiseEqual(field.at(v), r.field.at(v))) << "vertex " << v;
  }
  EXPECT_GT(changedInside, 0);
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), r.curves.size());
  for (const std::string& line : r.report.lines()) EXPECT_FALSE(line.empty());
  EXPECT_NE(r.report.lines().back().find(std::to_string(before.size()) + " curves -> "),
            std::string::npos);
}

void expectEachRemoved(const std::shared_ptr<const TetMesh>& mesh) {
  for (const Scenario& s : kScenarios) {
    try {
      expectRemoved(mesh, s);
    } catch (const Error& e) {
      ADD_FAILURE() << s.name << ": " << e.what();
    }
  }
}

TEST(RemoveCurves, EachScenarioOnABox) { expectEachRemoved(testing::jitteredBox(12, 0.15)); }

TEST(RemoveCurves, EachScenarioOnABall) { expectEachRemoved(testing::carvedBall(14)); }

TEST(RemoveCurves, TheCurvesAreWhatTheFieldsSay) {
  // The known-curve fields behave as designed: one mixed loop, one open curve with a wedge and
  // a trisector end, a pure wedge and a pure trisector line.
  const auto mesh = testing::jitteredBox(12, 0.15);
  const DegenerateCurves l = extractDegenerateCurves(testing::designedField(mesh, loop));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_TRUE(l.curve(0).closed);
  EXPECT_EQ(l.curve(0).type, DegenerateType::Linear);
  const PatternCounts lc = patternCounts(l.curve(0));
  EXPECT_GT(lc.wedge, 0);
  EXPECT_GT(lc.trisector, 0);
  const DegenerateCurves t = extractDegenerateCurves(testing::designedField(mesh, lines));
  ASSERT_EQ(t.size(), 2u);
  const PatternCounts a = patternCounts(t.curve(0)), b = patternCounts(t.curve(1));
  EXPECT_EQ(a.wedge * a.trisector, 0);
  EXPECT_EQ(b.wedge * b.trisector, 0);
  EXPECT_NE(a.wedge > 0, b.wedge > 0);
}

TEST(RemoveCurves, RefusesAPureLoopAlone) {
  const auto box = testing::jitteredBox(16, 0.15);
  const auto torus = testing::keepTets(
      *box, [](const Vec3& c) { return std::hypot(std::hypot(c.x(), c.y()) - 0.6, c.z()) < 0.32; });
  const TensorField field = testing::designedField(
      torus, [](const Vec3& p) { return testing::coreCircleW(p); }, testing::turningFrame);
  const DegenerateCurves curves = extractDegenerateCurves(field);
  ASSERT_EQ(curves.size(), 1u) << curves.summary();
  ASSERT_TRUE(curves.curve(0).closed);
  const PatternCounts n = patternCounts(curves.curve(0));
  ASSERT_EQ(n.wedge * n.trisector, 0) << "a pure loop";
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.6, 0, 0)};
  try {
    removeCurves(field, o);
    FAIL() << "a pure loop was removed alone";
  } catch (const RemovalRefused& e) {
    EXPECT_NE(std::string(e.what()).find("loop: it cannot be removed alone"), std::string::npos)
        << e.what();
  }
}

TEST(RemoveCurves, RefusesAPureLineAloneAndALineWithALoop) {
  const auto mesh = testing::jitteredBox(12, 0.15);
  const TensorField field = testing::designedField(mesh, lines);
  RemoveCurvesOptions o;
  o.picks = {Vec3(-0.3, 0, 0)};
  EXPECT_THROW(removeCurves(field, o), RemovalRefused);
  try {
    removeCurves(field, o);
  } catch (const RemovalRefused& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be removed alone"), std::string::npos);
  }
  // Same pick twice is one target.
  o.picks = {Vec3(-0.3, 0, 0), Vec3(-0.31, 0, 0.2)};
  EXPECT_THROW(removeCurves(field, o), RemovalRefused);
}

TEST(RemoveCurves, RefusesALoopThreadedByAnotherCurveNamingItAndItsDistance) {
  const auto mesh = testing::jitteredBox(14, 0.15);
  const TensorField field =
      testing::designedField(mesh, [](const Vec3& p) { return testing::linkedW(p); });
  const DegenerateCurves curves = extractDegenerateCurves(field);
  ASSERT_EQ(curves.size(), 2u) << curves.summary();
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.45, 0, 0)};
  try {
    removeCurves(field, o);
    FAIL() << "the threaded loop was removed";
  } catch (const RemovalRefused& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("would have to cut it"), std::string::npos) << m;
    EXPECT_NE(m.find("avoids the linear curve through ("), std::string::npos) << m;
    EXPECT_NE(m.find(" away"), std::string::npos) << m;
  }
}

TEST(RemoveCurves, BadInputIsAClearError) {
  const auto mesh = testing::jitteredBox(6, 0.1);
  const TensorField field = testing::designedField(mesh, loop);
  RemoveCurvesOptions o;
  EXPECT_THROW(removeCurves(field, o), Error);  // no pick
  o.picks = {Vec3(0, 0, std::nan(""))};
  EXPECT_THROW(removeCurves(field, o), Error);
  const TensorField flat = testing::designedField(mesh, [](const Vec3&) { return Complex(1, 0); });
  o.picks = {Vec3(0, 0, 0)};
  try {
    removeCurves(flat, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no degenerate curves"), std::string::npos);
  }
}

TEST(RemoveCurves, OneAndTwoThreadsGiveTheSameBits) {
  const auto mesh = testing::carvedBall(14);
  const TensorField field = testing::designedField(mesh, loop);
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.4, 0, 0)};
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    derivedCache().clear();  // each run builds its own solver set-up
    return removeCurves(field, o);
  };
  const RemoveCurvesResult a = run(1), b = run(2);
  EXPECT_EQ(a.regionTets, b.regionTets);
  for (int v = 0; v < int(mesh->vertexCount()); ++v)
    ASSERT_TRUE(bitwiseEqual(a.field.at(v), b.field.at(v))) << v;
  EXPECT_EQ(a.curves.size(), b.curves.size());
}

}  // namespace
}  // namespace tfd::core
