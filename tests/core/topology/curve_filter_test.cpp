// Curve selection after extraction: the curves a boundary-conforming field has in the first
// layer of tets are recognised (and only they), and filtering keeps the designed curve.
#include <gtest/gtest.h>

#include "core/design/propagate.h"
#include "core/error.h"
#include "core/topology/curve_filter.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

struct Designed {
  std::shared_ptr<const TetMesh> mesh;
  DegenerateCurves curves;
};

/// A ball (structured, mapped onto the sphere) with one L-wedge point element at the origin (its
/// curve runs along z through the ball), propagated boundary-conforming.
const Designed& designedBall() {
  static const Designed d = [] {
    auto mesh = test::mappedBall(17);  // 29478 tets
    ConstraintSet set;
    PointElement e;
    e.degenerate = true;
    e.field = makeDegenerateLinearization(Vec3(0.02, 0.01, 0.03), Mat3::Identity(),
                                          DegenerateType::Linear, DegeneratePattern::Wedge);
    set.points.push_back(e);
    TensorField field = propagate(mesh, set).field;
    return Designed{mesh, extractDegenerateCurves(field)};
  }();
  return d;
}

TEST(CurveFilter, CurvesHuggingTheBoundaryStayWithinOneLayerOfTets) {
  const Designed& d = designedBall();
  const double h = d.mesh->meanEdgeLength();
  int hugging = 0;
  for (const DegenerateCurve& c : d.curves.curves()) {
    if (!hugsBoundary(c, *d.mesh)) continue;
    ++hugging;
    for (const Vec3& p : c.points) EXPECT_GT(p.norm(), 1 - 2 * h) << "curve " << c.id;
  }
  EXPECT_GT(hugging, 0) << "a boundary-conforming field has such curves: the check is not vacuous";
  EXPECT_EQ(hugging, boundaryCurveCount(d.curves, *d.mesh));
}

TEST(CurveFilter, DroppingBoundaryCurvesKeepsTheDesignedCurveThroughTheCentre) {
  const Designed& d = designedBall();
  CurveFilter filter;
  filter.dropBoundary = true;
  const DegenerateCurves kept = filterCurves(d.curves, *d.mesh, filter);
  EXPECT_EQ(kept.size() + boundaryCurveCount(d.curves, *d.mesh), d.curves.size());
  const auto pick = kept.pick(Vec3(0.02, 0.01, 0.03));
  ASSERT_TRUE(pick.has_value());
  EXPECT_LT(pick->distance, d.mesh->meanEdgeLength());
  EXPECT_EQ(kept.curve(pick->curveId).type, DegenerateType::Linear);
  for (const DegenerateCurve& c : kept.curves()) EXPECT_FALSE(hugsBoundary(c, *d.mesh));
  for (int i = 0; i < int(kept.size()); ++i) EXPECT_EQ(kept.curves()[i].id, i) << "renumbered";
}

TEST(CurveFilter, MinLengthDropsExactlyTheShortCurves) {
  const Designed& d = designedBall();
  CurveFilter filter;
  filter.minLength = 0.5;
  const DegenerateCurves kept = filterCurves(d.curves, *d.mesh, filter);
  std::size_t long_ = 0;
  for (const DegenerateCurve& c : d.curves.curves()) long_ += c.length() >= 0.5;
  EXPECT_EQ(kept.size(), long_);
  EXPECT_GE(kept.size(), 1u) << "the designed curve crosses the ball";
  filter.minLength = -1;
  EXPECT_THROW(filterCurves(d.curves, *d.mesh, filter), Error);
}

}  // namespace
}  // namespace tfd::core
