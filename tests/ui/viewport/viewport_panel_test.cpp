// The viewport panel's scene, offscreen (what it would draw, without OpenGL): the display
// node's cooked output, a change of display flag drawn from the last cook without a new one, the
// cutting plane, the selected node's overlay, and nothing of a previous file after New.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>

#include <thread>

#include "nodes/register_all.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/viewport/viewport_panel.h"

namespace tfd::ui {
namespace {

class Viewport : public ::testing::Test {
 protected:
  void SetUp() override {
    nodes::registerAll(registry);
    doc = std::make_unique<GraphDocument>(registry);
    cook = std::make_unique<CookController>(*doc);
    panel = std::make_unique<ViewportPanel>(*doc, *cook);
    cook->setAutoCook(false);
    doc->addNode("TetMesh", {}, "mesh");
    doc->setParam("mesh", "primitive", std::string("box"));
    doc->setParam("mesh", "target_tets", std::int64_t{3000});
    doc->addNode("FieldExpression", {}, "field");
    const char* linear[] = {"x + 0.3", "y - 0.2", "-x - y", "z", "0.5 * x + 0.1", "0.4 * y"};
    const char* names[] = {"xx", "yy", "zz", "xy", "yz", "xz"};
    for (int i = 0; i < 6; ++i) doc->setParam("field", names[i], std::string(linear[i]));
    doc->addNode("ExtractDegenerateCurves", {}, "curves");
    doc->connect({"mesh", "mesh"}, {"field", "mesh"});
    doc->connect({"field", "field"}, {"curves", "field"});
    cook->setAutoCook(true);
    waitForCooks(1);
  }
  void TearDown() override {
    panel.reset();
    cook.reset();
    doc.reset();
  }
  void waitForCooks(int n) {
    QElapsedTimer t;
    t.start();
    while ((cook->finishedCooks() < n || cook->isCooking()) && t.elapsed() < 60000) {
      QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_GE(cook->finishedCooks(), n);
  }
  const render::Scene& scene() const { return panel->view()->scene(); }

  graph::NodeRegistry registry;
  std::unique_ptr<GraphDocument> doc;
  std::unique_ptr<CookController> cook;
  std::unique_ptr<ViewportPanel> panel;
};

TEST_F(Viewport, ShowsTheDisplayNodesCookedOutput) {
  EXPECT_EQ(panel->shownNode(), "curves") << "the last node with outputs";
  EXPECT_GT(scene().curves.segmentCount(), 10u);
  EXPECT_GT(scene().boundary.indices.size(), 100u) << "the boundary of the mesh upstream";
  EXPECT_TRUE(scene().slice.positions.empty());
}

TEST_F(Viewport, AnotherDisplayFlagIsDrawnFromTheLastCookWithoutANewOne) {
  ASSERT_TRUE(doc->setDisplayNode("mesh"));
  QCoreApplication::processEvents();
  EXPECT_EQ(panel->shownNode(), "mesh");
  EXPECT_EQ(scene().curves.segmentCount(), 0u);
  EXPECT_GT(scene().boundary.indices.size(), 100u);
  EXPECT_EQ(cook->finishedCooks(), 1) << "the display flag does not cook";
  EXPECT_FALSE(cook->isCooking());
}

TEST_F(Viewport, TheCuttingPlaneAndTheSelectedNodesOverlay) {
  render::SliceSettings s;
  s.axis = 0;
  s.quantity = render::SliceQuantity::Degeneracy;
  panel->setSlice(s);
  EXPECT_GT(scene().slice.positions.size(), 9u * 20);
  ASSERT_TRUE(panel->slice());
  EXPECT_EQ(panel->slice()->axis, 0);
  panel->setSlice(std::nullopt);
  EXPECT_TRUE(scene().slice.positions.empty());
  ASSERT_FALSE(doc->addNode("LocalSmooth", {}, "smooth").empty());
  panel->setSelectedNode("smooth");
  EXPECT_EQ(scene().markers.positions.size(), 3u) << "its pick";
  EXPECT_GT(scene().overlay.segmentCount(), 100u) << "its sphere region";
  panel->setSelectedNode("");
  EXPECT_TRUE(scene().markers.positions.empty());
}

TEST_F(Viewport, NewLeavesNothingOfThePreviousFile) {
  doc->newDocument();
  EXPECT_EQ(panel->shownNode(), "");
  EXPECT_TRUE(scene().empty());
}

}  // namespace
}  // namespace tfd::ui
