// The editor's document: undoable, validated edits over graph::Graph (offscreen, no GL).
#include <gtest/gtest.h>

#include "graph/graph_file.h"
#include "nodes/display_values.h"
#include "nodes/register_all.h"
#include "tests/support/temp_dir.h"
#include "ui/document/graph_document.h"
#include "ui/document/node_ui.h"

namespace tfd::ui {
namespace {

class Document : public ::testing::Test {
 protected:
  void SetUp() override { nodes::registerAll(registry); }
  graph::NodeRegistry registry;
};

TEST_F(Document, CreateAndConnectAreUndoableSteps) {
  GraphDocument doc(registry);
  EXPECT_EQ(doc.addNode("TetMesh", {10, 20}, "ball"), "ball");
  EXPECT_EQ(doc.addNode("Propagate", {200, 20}), "propagate1");
  EXPECT_TRUE(doc.connect({"ball", "mesh"}, {"propagate1", "mesh"}));
  EXPECT_EQ(doc.graph().links().size(), 1u);
  EXPECT_EQ(doc.undoStack()->count(), 3);
  EXPECT_EQ(nodePosition(doc.graph().node("ball")), QPointF(10, 20));
  doc.undoStack()->undo();
  EXPECT_TRUE(doc.graph().links().empty());
  doc.undoStack()->undo();
  EXPECT_EQ(doc.graph().nodeCount(), 1u);
  doc.undoStack()->redo();
  doc.undoStack()->redo();
  EXPECT_EQ(doc.graph().links().size(), 1u);
}

TEST_F(Document, TypeMismatchedConnectionIsRefusedWithoutAStep) {
  GraphDocument doc(registry);
  doc.addNode("TetMesh", {}, "ball");
  doc.addNode("Propagate", {}, "field");
  const int steps = doc.undoStack()->count();
  const auto before = doc.revision();
  int refused = 0;
  QObject::connect(&doc, &GraphDocument::editRefused, [&](const QString&) { ++refused; });
  EXPECT_FALSE(doc.canConnect({"ball", "mesh"}, {"field", "constraints"}));
  EXPECT_FALSE(doc.connect({"ball", "mesh"}, {"field", "constraints"}));
  EXPECT_NE(doc.lastError().find("output ball.mesh is TetMesh but input field.constraints takes "
                                 "Constraints"),
            std::string::npos)
      << doc.lastError();
  EXPECT_EQ(refused, 1);
  EXPECT_EQ(doc.undoStack()->count(), steps);
  EXPECT_EQ(doc.revision(), before);
  EXPECT_TRUE(doc.graph().links().empty());
  EXPECT_FALSE(doc.setParam("ball", "target_tets", std::int64_t{-5}));
  EXPECT_EQ(doc.undoStack()->count(), steps);
}

TEST_F(Document, ASecondLinkIntoASingleInputReplacesTheFirstInOneStep) {
  GraphDocument doc(registry);
  doc.addNode("TetMesh", {}, "a");
  doc.addNode("TetMesh", {}, "b");
  doc.addNode("Propagate", {}, "field");
  ASSERT_TRUE(doc.connect({"a", "mesh"}, {"field", "mesh"}));
  ASSERT_TRUE(doc.connect({"b", "mesh"}, {"field", "mesh"}));
  ASSERT_EQ(doc.graph().links().size(), 1u);
  EXPECT_EQ(doc.graph().links()[0].from.node, "b");
  doc.undoStack()->undo();
  EXPECT_EQ(doc.graph().links()[0].from.node, "a");
}

TEST_F(Document, UndoAndRedoRoundTripToByteIdenticalText) {
  GraphDocument doc(registry);
  doc.open(TFD_SOURCE_DIR "/examples/default.tfd.json");
  std::vector<std::string> texts{doc.text()};
  auto step = [&](bool ok) {
    ASSERT_TRUE(ok) << doc.lastError();
    texts.push_back(doc.text());
  };
  step(doc.setParam("ball", "target_tets", std::int64_t{5000}));
  step(!doc.addNode("LocalSmooth", {600, 500}, "smooth").empty());
  step(doc.connect({"field", "field"}, {"smooth", "field"}));
  step(doc.setParam("smooth", "pick", graph::Vec3Param{0.1, 0.2, 0.3}));
  step(doc.remove({"design"}));
  step(doc.moveNodes({{"ball", {5, 7}}, {"field", {300, 40}}}));
  step(doc.setDisplayNode("field"));
  step(doc.renameNode("topology", "curves"));
  step(!doc.duplicate({"linear_wedge", "planar_wedge"}).empty());
  ASSERT_EQ(doc.undoStack()->count(), static_cast<int>(texts.size()) - 1);
  for (int i = static_cast<int>(texts.size()) - 2; i >= 0; --i) {
    doc.undoStack()->undo();
    ASSERT_EQ(doc.text(), texts[i]) << "after undoing step " << i + 1;
  }
  for (std::size_t i = 1; i < texts.size(); ++i) {
    doc.undoStack()->redo();
    ASSERT_EQ(doc.text(), texts[i]) << "after redoing step " << i;
  }
}

TEST_F(Document, DeleteRemovesLinksAndUndoRestoresOrder) {
  GraphDocument doc(registry);
  doc.open(TFD_SOURCE_DIR "/examples/default.tfd.json");
  const std::string original = doc.text();
  const auto links = doc.graph().links().size();
  ASSERT_TRUE(doc.remove({"field"}, {doc.graph().links().front()}));
  EXPECT_EQ(doc.graph().findNode("field"), nullptr);
  EXPECT_LT(doc.graph().links().size(), links - 5);
  for (const graph::Link& l : doc.graph().links()) {
    EXPECT_NE(l.from.node, "field");
    EXPECT_NE(l.to.node, "field");
  }
  doc.undoStack()->undo();
  EXPECT_EQ(doc.text(), original);
}

TEST_F(Document, CopyIsGraphFileTextAndPasteRenamesAndKeepsInnerLinks) {
  GraphDocument doc(registry);
  doc.open(TFD_SOURCE_DIR "/examples/default.tfd.json");
  const std::string text = doc.copyText({"field", "ball", "topology"});
  // The clipboard holds a graph file: it loads on its own, nodes in document order.
  graph::Graph copied = graph::parseGraph(text, registry, "clipboard");
  ASSERT_EQ(copied.nodeCount(), 3u);
  EXPECT_EQ(copied.nodes()[0].name(), "ball");
  EXPECT_EQ(copied.nodes()[2].name(), "topology");
  ASSERT_EQ(copied.links().size(), 2u);  // ball->field, field->topology; not design->field
  EXPECT_EQ(std::get<std::int64_t>(copied.param("ball", "target_tets")), 60000);

  const auto before = doc.graph().nodeCount();
  std::vector<std::string> added = doc.paste(text, {100, 50});
  ASSERT_EQ(added, (std::vector<std::string>{"ball1", "field1", "topology1"}));
  EXPECT_EQ(doc.graph().nodeCount(), before + 3);
  EXPECT_EQ(doc.graph().linksInto("field1", "mesh").at(0).from.node, "ball1");
  EXPECT_TRUE(doc.graph().linksInto("field1", "constraints").empty());
  EXPECT_EQ(nodePosition(doc.graph().node("field1")),
            nodePosition(doc.graph().node("field")) + QPointF(100, 50));
  EXPECT_EQ(doc.undoStack()->undoText(), "Paste");

  // Text edited by hand (or from another file) pastes too; garbage is refused.
  EXPECT_TRUE(doc.paste("{\"nodes\": {}}").empty());
  EXPECT_NE(doc.lastError().find("paste: clipboard"), std::string::npos) << doc.lastError();
}

TEST_F(Document, DuplicateCopiesParametersAndDropsTheDisplayFlag) {
  GraphDocument doc(registry);
  doc.addNode("PointConstraint", {}, "p");
  doc.setParam("p", "position", graph::Vec3Param{0.25, 0, 0});
  doc.setDisplayNode("p");
  auto added = doc.duplicate({"p"});
  ASSERT_EQ(added, std::vector<std::string>{"p1"});
  EXPECT_EQ(doc.graph().param("p1", "position"), graph::ParamValue(graph::Vec3Param{0.25, 0, 0}));
  EXPECT_TRUE(nodes::hasDisplayFlag(doc.graph().node("p")));
  EXPECT_FALSE(nodes::hasDisplayFlag(doc.graph().node("p1")));
  EXPECT_EQ(nodePosition(doc.graph().node("p1")), QPointF(40, 40));
}

TEST_F(Document, ASliderScrubIsOneUndoStep) {
  GraphDocument doc(registry);
  doc.addNode("Propagate", {}, "f");
  const int steps = doc.undoStack()->count();
  for (double v : {1e-7, 1e-6, 1e-5}) EXPECT_TRUE(doc.setParam("f", "tolerance", v, true));
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  doc.closeContinuousEdit();
  EXPECT_TRUE(doc.setParam("f", "tolerance", 1e-4, true));
  EXPECT_EQ(doc.undoStack()->count(), steps + 2);
  doc.undoStack()->undo();
  EXPECT_EQ(doc.graph().param("f", "tolerance"), graph::ParamValue(1e-5));
  doc.undoStack()->undo();
  EXPECT_EQ(doc.graph().param("f", "tolerance"), graph::ParamValue(1e-8));
  // Setting the value a parameter already has is no step.
  EXPECT_TRUE(doc.setParam("f", "tolerance", 1e-8));
  EXPECT_EQ(doc.undoStack()->index(), steps);
}

TEST_F(Document, TheDisplayFlagIsOnOneNodeOnly) {
  GraphDocument doc(registry);
  doc.addNode("TetMesh", {}, "a");
  doc.addNode("TetMesh", {}, "b");
  EXPECT_EQ(nodes::displayNodeName(doc.graph()), "b");  // default: the last node with outputs
  doc.setDisplayNode("a");
  EXPECT_EQ(nodes::displayNodeName(doc.graph()), "a");
  doc.setDisplayNode("b");
  EXPECT_FALSE(nodes::hasDisplayFlag(doc.graph().node("a")));
  EXPECT_TRUE(nodes::hasDisplayFlag(doc.graph().node("b")));
  EXPECT_FALSE(doc.setDisplayNode("nope"));
}

TEST_F(Document, EveryChangeIsAnnouncedBeforeItHappens) {
  GraphDocument doc(registry);
  std::vector<std::string> events;
  QObject::connect(&doc, &GraphDocument::aboutToChange,
                   [&] { events.push_back("about:" + std::to_string(doc.graph().nodeCount())); });
  QObject::connect(&doc, &GraphDocument::changed, [&](int) {
    events.push_back("changed:" + std::to_string(doc.graph().nodeCount()));
  });
  doc.addNode("TetMesh");
  doc.undoStack()->undo();
  EXPECT_EQ(events, (std::vector<std::string>{"about:0", "changed:1", "about:1", "changed:0"}));
}

TEST_F(Document, SaveMarksCleanAndEditsMarkDirty) {
  test::TempDir dir("ui-doc-save");
  GraphDocument doc(registry);
  EXPECT_FALSE(doc.isDirty());
  doc.addNode("TetMesh", {}, "ball");
  EXPECT_TRUE(doc.isDirty());
  const auto path = dir.path() / "a.tfd.json";
  doc.save(path);
  EXPECT_FALSE(doc.isDirty());
  EXPECT_EQ(doc.filePath(), path);
  EXPECT_EQ(graph::readTextFile(path), doc.text());
  doc.setParam("ball", "target_tets", std::int64_t{1000});
  EXPECT_TRUE(doc.isDirty());
  doc.undoStack()->undo();
  EXPECT_FALSE(doc.isDirty()) << "back at the saved state";
  GraphDocument other(registry);
  other.open(path);
  EXPECT_EQ(other.text(), doc.text());
  EXPECT_EQ(other.undoStack()->count(), 0);
}

}  // namespace
}  // namespace tfd::ui
