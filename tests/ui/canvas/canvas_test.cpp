// The node canvas over the document (offscreen): items from declarations, link dragging with
// compatible ports lit, box select, moves as one undo step, framing, zoom, badges, Tab menu.
#include <gtest/gtest.h>

#include <QApplication>
#include <QMouseEvent>

#include "nodes/display_values.h"
#include "nodes/register_all.h"
#include "ui/canvas/canvas_scene.h"
#include "ui/canvas/canvas_view.h"
#include "ui/canvas/link_item.h"
#include "ui/canvas/node_menu.h"
#include "ui/document/graph_document.h"
#include "ui/document/node_ui.h"

namespace tfd::ui {
namespace {

class Canvas : public ::testing::Test {
 protected:
  void SetUp() override {
    nodes::registerAll(registry);
    doc = std::make_unique<GraphDocument>(registry);
    scene = std::make_unique<CanvasScene>(*doc);
    view = std::make_unique<CanvasView>(scene.get());
    view->resize(900, 600);
    view->show();
  }
  void TearDown() override {
    view.reset();
    scene.reset();
    doc.reset();
  }
  /// Sends a mouse event to the view's viewport at a scene position.
  void mouse(QEvent::Type type, QPointF scenePos, Qt::MouseButtons buttons,
             Qt::KeyboardModifiers mods = Qt::NoModifier) {
    const QPoint at = view->mapFromScene(scenePos);
    const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent e(type, QPointF(at), view->viewport()->mapToGlobal(QPointF(at)), button, buttons,
                  mods);
    QApplication::sendEvent(view->viewport(), &e);
  }
  void drag(QPointF from, QPointF to) {
    mouse(QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int i = 1; i <= 4; ++i)
      mouse(QEvent::MouseMove, from + (to - from) * (i / 4.0), Qt::LeftButton);
    mouse(QEvent::MouseButtonRelease, to, Qt::NoButton);
  }
  QPointF port(const std::string& node, bool output, const std::string& name) {
    NodeItem* item = scene->nodeItem(node);
    const auto& d = item->decl();
    return item->portScenePos({output, output ? d.outputIndex(name) : d.inputIndex(name)});
  }

  graph::NodeRegistry registry;
  std::unique_ptr<GraphDocument> doc;
  std::unique_ptr<CanvasScene> scene;
  std::unique_ptr<CanvasView> view;
};

TEST_F(Canvas, ItemsMirrorTheDocumentAndItsDeclarations) {
  doc->open(TFD_SOURCE_DIR "/examples/default.tfd.json");
  EXPECT_EQ(scene->nodeItems().size(), doc->graph().nodeCount());
  EXPECT_EQ(scene->linkItems().size(), doc->graph().links().size());
  NodeItem* field = scene->nodeItem("field");
  ASSERT_NE(field, nullptr);
  EXPECT_EQ(field->pos(), QPointF(500, 150));
  EXPECT_EQ(field->decl().inputs().size(), 2u);
  EXPECT_EQ(field->portAt(port("field", false, "constraints")), (PortRef{false, 1}));
  doc->remove({"field"});
  EXPECT_EQ(scene->nodeItem("field"), nullptr);
  EXPECT_EQ(scene->linkItems().size(), doc->graph().links().size());
  doc->undoStack()->undo();
  EXPECT_NE(scene->nodeItem("field"), nullptr);
  EXPECT_EQ(scene->linkItems().size(), doc->graph().links().size());
}

TEST_F(Canvas, DraggingFromAPortLightsOnlyCompatiblePortsAndLinks) {
  doc->addNode("TetMesh", {0, 0}, "mesh");
  doc->addNode("Propagate", {300, 0}, "prop");
  doc->addNode("FieldExpression", {300, 150}, "expr");
  doc->addNode("LocalSmooth", {600, 0}, "smooth");
  mouse(QEvent::MouseButtonPress, port("mesh", true, "mesh"), Qt::LeftButton);
  ASSERT_TRUE(scene->linkDragActive());
  auto lit = scene->highlightedPorts();
  std::vector<std::pair<std::string, PortRef>> expected{{"prop", {false, 0}}, {"expr", {false, 0}}};
  EXPECT_EQ(lit, expected);
  mouse(QEvent::MouseMove, port("prop", false, "mesh"), Qt::LeftButton);
  mouse(QEvent::MouseButtonRelease, port("prop", false, "mesh"), Qt::NoButton);
  EXPECT_FALSE(scene->linkDragActive());
  EXPECT_TRUE(scene->highlightedPorts().empty());
  ASSERT_EQ(doc->graph().links().size(), 1u);
  EXPECT_EQ(doc->graph().links()[0].to.str(), "prop.mesh");
  EXPECT_EQ(scene->linkItems().size(), 1u);

  // An incompatible port: nothing happens.
  const int steps = doc->undoStack()->count();
  drag(port("mesh", true, "mesh"), port("smooth", false, "field"));
  EXPECT_EQ(doc->undoStack()->count(), steps);

  // Dragging backwards, from an input to an output, works too.
  drag(port("smooth", false, "field"), port("prop", true, "field"));
  EXPECT_EQ(doc->graph().linksInto("smooth", "field").size(), 1u);
}

TEST_F(Canvas, ALinkDroppedOnEmptySpaceOffersMatchingTypes) {
  doc->addNode("TetMesh", {0, 0}, "mesh");
  std::optional<LinkStart> dropped;
  QObject::connect(scene.get(), &CanvasScene::linkDroppedOnEmpty,
                   [&](QPointF, QPoint, LinkStart s) { dropped = s; });
  drag(port("mesh", true, "mesh"), QPointF(400, 300));
  ASSERT_TRUE(dropped.has_value());
  EXPECT_EQ(dropped->endpoint.str(), "mesh.mesh");
  EXPECT_TRUE(view->nodeMenu()->isVisible());
  const QStringList offered = view->nodeMenu()->visibleTypes();
  EXPECT_TRUE(offered.contains("Propagate"));
  EXPECT_TRUE(offered.contains("FieldExpression"));
  EXPECT_FALSE(offered.contains("ExtractDegenerateCurves"));
  view->nodeMenu()->setFilterText("propag");
  ASSERT_EQ(view->nodeMenu()->visibleTypes(), QStringList{"Propagate"});
  const int steps = doc->undoStack()->count();
  ASSERT_TRUE(view->nodeMenu()->activateCurrent());
  EXPECT_EQ(doc->undoStack()->count(), steps + 1) << "add and link are one step";
  ASSERT_EQ(doc->graph().links().size(), 1u);
  EXPECT_EQ(doc->graph().links()[0].to.str(), "propagate1.mesh");
  EXPECT_EQ(scene->selectedNodeNames(), std::vector<std::string>{"propagate1"});
}

TEST_F(Canvas, ALinkPickedUpFromAnInputMovesOrGoes) {
  doc->addNode("TetMesh", {0, 0}, "mesh");
  doc->addNode("Propagate", {300, 0}, "a");
  doc->addNode("Propagate", {300, 200}, "b");
  doc->connect({"mesh", "mesh"}, {"a", "mesh"});
  drag(port("a", false, "mesh"), port("b", false, "mesh"));
  ASSERT_EQ(doc->graph().links().size(), 1u);
  EXPECT_EQ(doc->graph().links()[0].to.str(), "b.mesh");
  drag(port("b", false, "mesh"), QPointF(700, 500));
  EXPECT_TRUE(doc->graph().links().empty());
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  EXPECT_EQ(doc->graph().links()[0].to.str(), "a.mesh");
}

TEST_F(Canvas, BoxSelectAndMoveAreOneUndoStep) {
  doc->addNode("TetMesh", {0, 0}, "a");
  doc->addNode("TetMesh", {0, 100}, "b");
  doc->addNode("TetMesh", {600, 400}, "far");
  view->frameAll();
  // Rubber band from above-left of a to below-right of b (empty space).
  drag(QPointF(-30, -30), QPointF(200, 160));
  EXPECT_EQ(scene->selectedNodeNames(), (std::vector<std::string>{"a", "b"}));
  const int steps = doc->undoStack()->count();
  drag(QPointF(90, 10), QPointF(190, 60));  // grab a's header and drag
  EXPECT_EQ(doc->undoStack()->count(), steps + 1);
  EXPECT_EQ(nodePosition(doc->graph().node("a")), QPointF(100, 50));
  EXPECT_EQ(nodePosition(doc->graph().node("b")), QPointF(100, 150));
  EXPECT_EQ(nodePosition(doc->graph().node("far")), QPointF(600, 400));
  doc->undoStack()->undo();
  EXPECT_EQ(scene->nodeItem("a")->pos(), QPointF(0, 0));
  EXPECT_EQ(scene->nodeItem("b")->pos(), QPointF(0, 100));
}

TEST_F(Canvas, FrameAllShowsEveryNodeAndZoomKeepsThePointUnderTheCursor) {
  doc->addNode("TetMesh", {-2000, -900}, "a");
  doc->addNode("TetMesh", {2500, 1200}, "b");
  view->frameAll();
  const QRectF visible = view->mapToScene(view->viewport()->rect()).boundingRect();
  for (NodeItem* item : scene->nodeItems())
    EXPECT_TRUE(visible.contains(item->sceneBoundingRect())) << item->name();
  scene->selectNodes({"b"});
  view->frameSelection();
  EXPECT_TRUE(view->mapToScene(view->viewport()->rect())
                  .boundingRect()
                  .contains(scene->nodeItem("b")->sceneBoundingRect()));
  EXPECT_FALSE(view->mapToScene(view->viewport()->rect())
                   .boundingRect()
                   .contains(scene->nodeItem("a")->sceneBoundingRect()));
  const QPoint cursor(200, 150);
  const QPointF before = view->mapToScene(cursor);
  const double z = view->zoom();
  view->zoomBy(1.5, cursor);
  EXPECT_NEAR(view->zoom(), std::min(4.0, z * 1.5), 1e-9);
  const QPointF after = view->mapToScene(cursor);
  EXPECT_NEAR(after.x(), before.x(), 3 / view->zoom());  // centerOn rounds to pixels
  EXPECT_NEAR(after.y(), before.y(), 3 / view->zoom());  // centerOn rounds to pixels
}

TEST_F(Canvas, BadgesAndTooltipsShowTheCookState) {
  doc->addNode("TetMesh", {0, 0}, "mesh");
  doc->addNode("Propagate", {300, 0}, "prop");
  NodeStatus failed;
  failed.state = NodeStatus::State::Failed;
  failed.messages = {{graph::Severity::Error, "TetGen failed: self-intersecting input"}};
  scene->setStatus("mesh", failed);
  NodeStatus upstream;
  upstream.state = NodeStatus::State::UpstreamFailed;
  upstream.failedNode = "mesh";
  scene->setStatus("prop", upstream);
  EXPECT_TRUE(scene->nodeItem("mesh")->toolTip().contains("self-intersecting input"));
  EXPECT_TRUE(scene->nodeItem("prop")->toolTip().contains("downstream of an error"));
  EXPECT_TRUE(scene->nodeItem("prop")->toolTip().contains("mesh"));
  // A status survives the node being re-created by undo (kept by name).
  doc->remove({"mesh"});
  doc->undoStack()->undo();
  EXPECT_EQ(scene->nodeItem("mesh")->status().state, NodeStatus::State::Failed);
}

TEST_F(Canvas, ClickingTheDisplayFlagMovesIt) {
  doc->addNode("TetMesh", {0, 0}, "a");
  doc->addNode("TetMesh", {0, 200}, "b");
  mouse(QEvent::MouseButtonPress, QPointF(5, 10), Qt::LeftButton);
  mouse(QEvent::MouseButtonRelease, QPointF(5, 10), Qt::NoButton);
  EXPECT_TRUE(nodes::hasDisplayFlag(doc->graph().node("a")));
  EXPECT_TRUE(scene->nodeItem("a")->displayFlag());
  mouse(QEvent::MouseButtonPress, QPointF(5, 210), Qt::LeftButton);
  mouse(QEvent::MouseButtonRelease, QPointF(5, 210), Qt::NoButton);
  EXPECT_FALSE(scene->nodeItem("a")->displayFlag());
  EXPECT_TRUE(scene->nodeItem("b")->displayFlag());
}

TEST_F(Canvas, TabOpensASearchableMenuByCategory) {
  view->setFocus();
  QKeyEvent tab(QEvent::KeyPress, Qt::Key_Tab, Qt::NoModifier);
  QApplication::sendEvent(view.get(), &tab);
  NodeMenu* menu = view->nodeMenu();
  ASSERT_TRUE(menu->isVisible());
  EXPECT_EQ(menu->visibleTypes().size(), static_cast<int>(registry.size()));
  menu->setFilterText("export");
  for (const QString& t : menu->visibleTypes())
    EXPECT_TRUE(t.startsWith("Export")) << t.toStdString();
  menu->setFilterText("topology");  // a category
  EXPECT_TRUE(menu->visibleTypes().contains("ExtractDegenerateCurves"));
  ASSERT_TRUE(menu->activateCurrent());
  EXPECT_EQ(doc->graph().nodeCount(), 1u);
}

TEST_F(Canvas, DeleteRemovesSelectedNodesAndLinksInOneStep) {
  doc->open(TFD_SOURCE_DIR "/examples/default.tfd.json");
  const std::string original = doc->text();
  scene->selectNodes({"vtu", "vdb"});
  scene->linkItems().front()->setSelected(true);
  const int steps = doc->undoStack()->count();
  ASSERT_TRUE(scene->deleteSelection());
  EXPECT_EQ(doc->undoStack()->count(), steps + 1);
  EXPECT_EQ(doc->graph().findNode("vtu"), nullptr);
  EXPECT_EQ(doc->graph().links().size(), 15u - 3 - 1);
  doc->undoStack()->undo();
  EXPECT_EQ(doc->text(), original);
}

}  // namespace
}  // namespace tfd::ui
