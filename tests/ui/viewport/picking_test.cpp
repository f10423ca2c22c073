// Viewport picking without OpenGL (offscreen): which parameter a click fills is read from the
// declarations by name, a click near a projected curve segment finds the point on it (the
// nearer of two overlapping ones), a click in space lands on the plane through the anchor
// under the cursor, and each pick is one undo step that undoes to byte-identical text.
#include <gtest/gtest.h>

#include "core/structured_mesh.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "ui/document/graph_document.h"
#include "ui/viewport/display_scene.h"
#include "ui/viewport/picking.h"

namespace tfd::ui {
namespace {

/// Stand-ins for edit nodes written elsewhere: a `picks` point list, and one with both.
void registerPickers(graph::NodeRegistry& r) {
  r.add(
      "ListPicker", 1,
      [](graph::NodeDecl& d) {
        d.doc("Picks curves.").category("Test");
        d.param<std::vector<graph::Vec3Param>>("picks").doc("Points on curves.");
      },
      [](graph::CookContext&) {});
  r.add(
      "BothPicker", 1,
      [](graph::NodeDecl& d) {
        d.doc("Both kinds.").category("Test");
        d.param<graph::Vec3Param>("pick");
        d.param<std::vector<graph::Vec3Param>>("picks");
      },
      [](graph::CookContext&) {});
}

class Picking : public ::testing::Test {
 protected:
  void SetUp() override {
    nodes::registerAll(registry);
    registerPickers(registry);
    camera.setPreset(render::ViewPreset::Z);  // looking down -z: x right, y up on screen
    render::Bounds b;
    b.extend(render::Vec3(-1, -1, -1));
    b.extend(render::Vec3(1, 1, 1));
    camera.frame(b, double(kW) / kH);
  }
  static constexpr int kW = 400, kH = 300;
  graph::NodeRegistry registry;
  render::Camera camera;
};

TEST_F(Picking, TheTargetComesFromTheDeclarations) {
  GraphDocument doc(registry);
  doc.addNode("LocalSmooth", {}, "smooth");
  doc.addNode("CurveConstraint", {}, "curve");
  doc.addNode("ListPicker", {}, "remove");
  doc.addNode("BothPicker", {}, "both");
  doc.addNode("Propagate", {}, "field");
  const auto& g = doc.graph();
  EXPECT_EQ(pickTargetFor(g.node("smooth")).kind, PickTarget::Kind::CurvePoint);
  EXPECT_EQ(pickTargetFor(g.node("smooth")).param, "pick");
  EXPECT_EQ(pickTargetFor(g.node("curve")).kind, PickTarget::Kind::SpacePoints);
  EXPECT_EQ(pickTargetFor(g.node("curve")).param, "points");
  EXPECT_EQ(pickTargetFor(g.node("remove")).kind, PickTarget::Kind::CurvePoints);
  EXPECT_EQ(pickTargetFor(g.node("both")).param, "picks") << "a list wins over a single pick";
  EXPECT_EQ(pickTargetFor(g.node("field")).kind, PickTarget::Kind::None);
  EXPECT_EQ(pickedPoints(g.node("curve")).size(), 3u) << "CurveConstraint's default points";
}

TEST_F(Picking, AClickNearACurveFindsThePointOnIt) {
  render::LineSet curves;
  curves.add({-0.5, 0.2, 0}, {0.5, 0.2, 0}, {}, {});
  const auto mid = camera.project({0.1, 0.2, 0}, kW, kH);
  ASSERT_TRUE(mid);
  const auto hit = pickCurvePoint(curves, camera, kW, kH, (*mid)[0], (*mid)[1] + 5);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->x(), 0.1, 0.01);
  EXPECT_NEAR(hit->y(), 0.2, 1e-6) << "the point is on the segment, not under the cursor";
  EXPECT_FALSE(pickCurvePoint(curves, camera, kW, kH, (*mid)[0], (*mid)[1] + 30))
      << "30 pixels away is not a click on the curve";
  // Beyond the segment's end: nothing.
  const auto end = camera.project({0.5, 0.2, 0}, kW, kH);
  EXPECT_FALSE(pickCurvePoint(curves, camera, kW, kH, (*end)[0] + 40, (*end)[1]));
}

TEST_F(Picking, OfTwoOverlappingCurvesTheNearerIsPicked) {
  render::LineSet curves;
  curves.add({-0.5, 0, -0.5}, {0.5, 0, -0.5}, {}, {});  // further from the eye (above +z)
  curves.add({-0.5, 0, 0.5}, {0.5, 0, 0.5}, {}, {});
  const auto mid = camera.project({0, 0, 0}, kW, kH);
  const auto hit = pickCurvePoint(curves, camera, kW, kH, (*mid)[0], (*mid)[1]);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->z(), 0.5, 1e-6);
}

TEST_F(Picking, AClickInSpaceLandsUnderTheCursorOnThePlaneThroughTheAnchor) {
  camera.setPreset(render::ViewPreset::Iso);
  camera.frame(render::Bounds{render::Vec3(-1, -1, -1), render::Vec3(1, 1, 1)}, double(kW) / kH);
  const render::Vec3 anchor(0.2, -0.1, 0.3);
  const render::Vec3 p = pointInSpace(camera, kW, kH, 123, 77, anchor);
  EXPECT_NEAR((p - anchor).dot(camera.backward()), 0, 1e-9);
  const auto back = camera.project(p, kW, kH);
  ASSERT_TRUE(back);
  EXPECT_NEAR((*back)[0], 123, 1e-6);
  EXPECT_NEAR((*back)[1], 77, 1e-6);
}

TEST_F(Picking, EachPickIsOneUndoStepAndUndoIsByteExact) {
  GraphDocument doc(registry);
  doc.addNode("ListPicker", {}, "remove");
  doc.addNode("LocalSmooth", {}, "smooth");
  doc.addNode("CurveConstraint", {}, "curve");
  const std::string before = doc.text();
  const int steps = doc.undoStack()->count();
  const PickTarget list = pickTargetFor(doc.graph().node("remove"));
  ASSERT_TRUE(applyPick(doc, list, {0.123456, -0.5, 1}));
  ASSERT_TRUE(applyPick(doc, list, {0.3, 0.2, 0.1}));
  using Points = std::vector<graph::Vec3Param>;
  EXPECT_EQ(std::get<Points>(doc.graph().node("remove").param("picks")),
            (Points{{0.1235, -0.5, 1}, {0.3, 0.2, 0.1}}));
  ASSERT_TRUE(applyPick(doc, pickTargetFor(doc.graph().node("smooth")), {0.25, 0, 0}));
  EXPECT_EQ(std::get<graph::Vec3Param>(doc.graph().node("smooth").param("pick")),
            (graph::Vec3Param{0.25, 0, 0}));
  ASSERT_TRUE(applyPick(doc, pickTargetFor(doc.graph().node("curve")), {0.7, 0.1, 0}));
  EXPECT_EQ(std::get<Points>(doc.graph().node("curve").param("points")).size(), 4u);
  EXPECT_EQ(doc.undoStack()->count(), steps + 4);
  for (int i = 0; i < 4; ++i) doc.undoStack()->undo();
  EXPECT_EQ(doc.text(), before);
}

TEST_F(Picking, TheSelectedNodeShowsItsRegionAndPicks) {
  GraphDocument doc(registry);
  doc.addNode("LocalSmooth", {}, "smooth");
  render::Scene scene;
  addSelectionOverlay(scene, doc.graph().node("smooth"));
  EXPECT_GT(scene.overlay.segmentCount(), 100u) << "the default sphere region is outlined";
  EXPECT_EQ(scene.markers.positions.size(), 3u) << "the pick is marked";
  doc.setParam("smooth", "region", std::string("box"));
  render::Scene box;
  addSelectionOverlay(box, doc.graph().node("smooth"));
  EXPECT_EQ(box.overlay.segmentCount(), 12u);
}

}  // namespace
}  // namespace tfd::ui
