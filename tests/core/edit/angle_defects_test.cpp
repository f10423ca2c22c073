// Held-boundary defects of the angle method of §6.3 (core/edit/angle_defects.h) and the
// removal that grows its region away from them (core/edit/remove_curves.h).
#include "core/edit/angle_defects.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/design/propagate.h"
#include "core/edit/remove_curves.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/recorded_point_constraints.h"

namespace tfd::core {
namespace {

Vec3 inPlane(double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  return Vec3(std::cos(a), std::sin(a), 0);
}

TEST(AngleDefects, LineFieldIndexCountsHalfTurns) {
  const std::array<Vec3, 3> up{Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()};
  EXPECT_EQ(lineFieldIndex(up, {inPlane(10), inPlane(20), inPlane(30)}), 0);
  // A line turning by 60° per edge comes back after half a turn: a wedge-like point inside.
  EXPECT_EQ(lineFieldIndex(up, {inPlane(0), inPlane(60), inPlane(120)}), 1);
  EXPECT_EQ(lineFieldIndex(up, {inPlane(0), inPlane(-60), inPlane(-120)}), -1);
  // The turn is measured against parallel transport: a tilted but untwisted frame has none.
  const Vec3 n1 = Vec3(0.3, 0, 1).normalized(), n2 = Vec3(0, 0.3, 1).normalized();
  const std::array<Vec3, 3> tilted{Vec3::UnitZ(), n1, n2};
  std::array<Vec3, 3> m;
  for (int i = 0; i < 3; ++i) m[i] = tilted[i].cross(Vec3(1, 0.2, 0)).normalized();
  EXPECT_EQ(lineFieldIndex(tilted, m), 0);
}

/// One field of bench/edit_bench.cpp's RandomRemovals (field 46: four point constraints,
/// boundary-conforming propagation on the jittered 14³ box), whose planar loop removal failed
/// the verification on every try before the region avoided the angle defects: two held faces
/// next to the box edge x = z = 1 where the medium eigenvector turns by half a turn (no
/// extracted curve passes there) gave the held angles a seam of 54 edges, and the solved field a
/// 46-point planar curve along it.
TensorField randomField46() {
  const auto mesh = testing::jitteredBox(14, 0.15);
  const testing::RecordedPoint raw[] = {
      {true,
       {0.013298873476327966, 0.44315309649992518, 0.11419148328064677},
       {0.094393569926493295, 0.42870085386605167, 0.89850177064436021, 0.0058340531049589171,
        -0.90275432077574846, 0.43011696100605656, 0.99551786411942433, -0.035358368390457182,
        -0.087715266652185361},
       {-1, -1, 2, 0, 0, 0},
       {1, -1, 0, 0, 0, 0},
       {0, 0, 0, 1, 0, 0},
       {0, 0, 0, 0, 0, 0}},
      {false,
       {0.29526340002467444, -0.36265347879543886, 0.41690636683845772},
       {-0.24716000370268518, 0.47748898273868334, 0.84315846905126079, 0.79689691264443407,
        -0.39485838611834329, 0.45721129199724109, 0.55124154704399575, 0.78491472547990493,
        -0.28291629599114221},
       {1.0065266705336076, -0.013053341067215059, -0.99347332946639244, 0, 0, 0},
       {},
       {},
       {}},
      {false,
       {0.29993121804958889, 0.15148697665619826, 0.0013211553772983775},
       {0.47110342364091312, 0.53939960656859831, 0.69793239548501529, 0.82377824895449503,
        -0.55192502909873364, -0.12949192563178616, 0.31535846394742029, 0.63594561614025102,
        -0.70435943418734748},
       {1.0106034208692078, -0.02120684173841577, -0.98939657913079215, 0, 0, 0},
       {},
       {},
       {}},
      {false,
       {0.3751027515249451, -0.48515116588544005, 0.37933029324454137},
       {-0.96721699261453487, -0.14141089118572284, -0.21093659960223715, 0.19532428147900135,
        -0.94508062697418371, -0.26205158572845072, -0.16229514552939261, -0.29466178641307283,
        0.94171902251438555},
       {0.9715153760796551, 0.056969247840689852, -1.0284846239203449, 0, 0, 0},
       {},
       {},
       {}},
  };
  return propagate(mesh, testing::recordedConstraints(raw), PropagateOptions{}).field;
}

TEST(AngleDefects, RemovalGrowsAwayFromHeldDefectsAndVerifies) {
  const TensorField field = randomField46();
  const DegenerateCurves before = extractDegenerateCurves(field);
  ASSERT_EQ(before.size(), 5u) << before.summary();
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.43810334956565011, -0.16606154211934337, 0.42539629266072893)};
  RemoveCurvesResult r{field, {}, {}, {}};
  try {
    r = removeCurves(field, o);
  } catch (const Error& e) {
    FAIL() << e.what();
  }
  EXPECT_EQ(r.report.scenario, RemovalScenario::OneLoop);
  EXPECT_GT(r.report.defectRegrowths, 0);
  EXPECT_GT(r.report.defectFaces, 0);
  EXPECT_EQ(r.curves.size(), before.size() - 1) << r.curves.summary();
  EXPECT_EQ(extractDegenerateCurves(r.field).size(), before.size() - 1);
  bool mentioned = false;
  for (const std::string& line : r.report.lines())
    mentioned = mentioned || line.find("turns by half a turn") != std::string::npos;
  EXPECT_TRUE(mentioned);
}

}  // namespace
}  // namespace tfd::core
