// Two-loop removal (paper §6.4, Fig. 17d; core/edit/remove_two_loops.h): a pure wedge loop and a
// pure trisector loop, concentric circles in a solid torus whose frame turns with them
// (removal_test_fields.h: e = φ̂, so each circle is pure), removed together by reconnecting them
// into one mixed loop and removing that; both steps verified and reported, nothing outside the
// two regions changed. Two loops of one pattern, or of different L/P types, are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/edit/remove_curves.h"
#include "core/region/region_vertices.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/removal_test_fields.h"

namespace tfd::core {
namespace {

using testing::Complex;

std::shared_ptr<const TetMesh> torus() {
  static const auto mesh = [] {
    const auto box = testing::jitteredBox(22, 0.15);
    return testing::keepTets(*box, [](const Vec3& c) {
      return std::hypot(std::hypot(c.x(), c.y()) - 0.6, c.z()) < 0.36;
    });
  }();
  return mesh;
}

/// Circles ρ = 0.45 and ρ = 0.75 in z = 0 (one wedge, one trisector; both of one pattern when
/// `same`). Scaled by 10 and bounded to |W| < 1 by a positive factor (zero set and patterns
/// unchanged): between the circles the product is small, and the linear interpolation of the
/// turning frame across an edge would otherwise add degenerate points of its own.
Complex twoCircles(const Vec3& p, bool same) {
  const double rho = std::hypot(p.x(), p.y());
  const Complex inner(rho - 0.45, p.z()), outer(rho - 0.75, p.z());
  const Complex w = 10.0 * inner * (same ? outer : std::conj(outer));
  return w / std::sqrt(1 + std::norm(w));
}

bool bitwiseEqual(const Tensor& a, const Tensor& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The field has exactly two curves, both pure (wedge-only or trisector-only) loops.
void expectTwoPureLoops(const DegenerateCurves& curves) {
  ASSERT_EQ(curves.size(), 2u) << curves.summary();
  for (const DegenerateCurve& c : curves.curves()) {
    ASSERT_TRUE(c.closed);
    const PatternCounts n = patternCounts(c);
    ASSERT_EQ(n.wedge * n.trisector, 0) << "a pure loop";
  }
}

/// Nothing outside the union of the two steps' regions changed (their held vertices included).
void expectOutsideUnchanged(const TensorField& before, const RemoveCurvesResult& r) {
  const TetMesh& mesh = before.mesh();
  const RegionVertices rv = regionVertices(mesh, r.regionTets);
  std::vector<char> inRegion(mesh.vertexCount(), 0);
  for (int v : rv.vertices) inRegion[v] = 1;
  for (int v = 0; v < int(mesh.vertexCount()); ++v)
    if (!inRegion[v]) {
      ASSERT_TRUE(bitwiseEqual(before.at(v), r.field.at(v))) << v;
    }
}

TEST(RemoveTwoLoops, APureWedgeLoopAndAPureTrisectorLoopCancel) {
  const auto mesh = torus();
  const TensorField field = testing::designedField(
      mesh, [](const Vec3& p) { return twoCircles(p, false); }, testing::turningFrame);
  expectTwoPureLoops(extractDegenerateCurves(field));
  if (::testing::Test::HasFatalFailure()) return;
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.45, 0, 0), Vec3(-0.75, 0, 0)};
  o.regionDistance = 0.25;
  const RemoveCurvesResult r = removeCurves(field, o);
  for (const std::string& line : r.report.lines()) std::printf("  %s\n", line.c_str());
  EXPECT_EQ(r.report.scenario, RemovalScenario::TwoLoop);
  EXPECT_EQ(r.curves.size(), 0u) << r.curves.summary();
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), 0u);
  ASSERT_FALSE(r.report.reconnection.empty());
  const std::vector<std::string> lines = r.report.lines();
  EXPECT_NE(lines.front().find("two-loop removal of "), std::string::npos) << lines.front();
  bool step1 = false, step2 = false;
  for (const std::string& line : lines) {
    step1 = step1 || line.find("step 1 (reconnection): pairing (Lemma 6.1") == 0;
    step2 = step2 || line.find("step 2: one-loop removal") == 0;
  }
  EXPECT_TRUE(step1 && step2);
  EXPECT_NE(lines.back().find("2 curves -> 0"), std::string::npos) << lines.back();
  expectOutsideUnchanged(field, r);
}

// Fig. 17d as the paper draws it: two concentric pure loops in a simply connected solid (a
// box), under a frame without an axis to avoid (removal_test_fields.h: swirlFrame). The merged
// loop bounds a band between the circles, so both regions stay around the circles: the far
// corners of the box keep their tensors.
TEST(RemoveTwoLoops, ConcentricLoopsInABoxAreRemovedLocally) {
  const auto mesh = testing::jitteredBox(18, 0.15);
  const TensorField field = testing::designedField(
      mesh, [](const Vec3& p) { return testing::twoCirclesW(p, 0.3, 0.55); },
      [](const Vec3& p) { return testing::swirlFrame(p); });
  expectTwoPureLoops(extractDegenerateCurves(field));
  if (::testing::Test::HasFatalFailure()) return;
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.3, 0, 0), Vec3(-0.55, 0, 0)};
  o.regionDistance = 0.2;
  const RemoveCurvesResult r = removeCurves(field, o);
  for (const std::string& line : r.report.lines()) std::printf("  %s\n", line.c_str());
  EXPECT_EQ(r.report.scenario, RemovalScenario::TwoLoop);
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), 0u);
  EXPECT_LT(r.regionTets.size(), mesh->tetCount() / 2);
  expectOutsideUnchanged(field, r);
}

TEST(RemoveTwoLoops, TwoLoopsOfOnePatternAreRefused) {
  const TensorField field = testing::designedField(
      torus(), [](const Vec3& p) { return twoCircles(p, true); }, testing::turningFrame);
  ASSERT_EQ(extractDegenerateCurves(field).size(), 2u);
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.45, 0, 0), Vec3(-0.75, 0, 0)};
  try {
    removeCurves(field, o);
    FAIL() << "two wedge loops were removed";
  } catch (const RemovalRefused& e) {
    EXPECT_NE(std::string(e.what()).find("pure wedge loop with a pure trisector loop"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tfd::core
