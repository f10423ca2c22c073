// The parameter panel generated from declarations (offscreen): editors per kind, edits as undo
// steps, a slider scrub as one step, validation as you type, the point table.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>
#include <QToolButton>

#include "nodes/register_all.h"
#include "ui/document/graph_document.h"
#include "ui/params/param_panel.h"
#include "ui/params/point_list_editor.h"

namespace tfd::ui {
namespace {

class Panel : public ::testing::Test {
 protected:
  void SetUp() override {
    nodes::registerAll(registry);
    doc = std::make_unique<GraphDocument>(registry);
    panel = std::make_unique<ParamPanel>(*doc);
  }
  void TearDown() override {
    panel.reset();
    doc.reset();
  }
  template <class W>
  W* child(const std::string& param) {
    ParamEditor* e = panel->editor(param);
    EXPECT_NE(e, nullptr) << param;
    return e ? e->findChild<W*>() : nullptr;
  }
  graph::NodeRegistry registry;
  std::unique_ptr<GraphDocument> doc;
  std::unique_ptr<ParamPanel> panel;
};

TEST_F(Panel, EveryParameterGetsAnEditorOfItsKind) {
  doc->addNode("TetMesh", {}, "mesh");
  panel->setNode("mesh");
  for (const graph::ParamDecl& d : registry.get("TetMesh").decl().params())
    EXPECT_NE(panel->editor(d.name), nullptr) << d.name;
  EXPECT_NE(child<QComboBox>("primitive"), nullptr);
  EXPECT_NE(child<QSpinBox>("target_tets"), nullptr);
  EXPECT_NE(child<QLineEdit>("file"), nullptr);
  EXPECT_NE(child<QToolButton>("file"), nullptr) << "file picker";
  QSlider* quality = child<QSlider>("quality");  // [0, 10]: a slider next to the spin box
  ASSERT_NE(quality, nullptr);
  doc->addNode("PointConstraint", {}, "p");
  panel->setNode("p");
  EXPECT_EQ(panel->editor("position")->findChildren<QDoubleSpinBox*>().size(), 3);
  doc->addNode("CurveConstraint", {}, "c");
  panel->setNode("c");
  EXPECT_NE(dynamic_cast<PointListEditor*>(panel->editor("points")), nullptr);
  EXPECT_NE(child<QCheckBox>("closed"), nullptr);
}

TEST_F(Panel, EditsAreUndoStepsAndUndoShowsInThePanel) {
  doc->addNode("TetMesh", {}, "mesh");
  panel->setNode("mesh");
  const int steps = doc->undoStack()->count();
  child<QSpinBox>("target_tets")->setValue(12345);
  EXPECT_EQ(doc->graph().param("mesh", "target_tets"), graph::ParamValue(std::int64_t{12345}));
  child<QComboBox>("primitive")->setCurrentText("box");
  EXPECT_EQ(doc->graph().param("mesh", "primitive"), graph::ParamValue(std::string("box")));
  EXPECT_EQ(doc->undoStack()->count(), steps + 2);
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  EXPECT_EQ(child<QSpinBox>("target_tets")->value(),
            std::get<std::int64_t>(
                registry.get("TetMesh").decl().findParam("target_tets")->defaultValue));
  EXPECT_EQ(child<QComboBox>("primitive")->currentText(), "sphere");
  EXPECT_EQ(doc->undoStack()->index(), steps) << "showing a value is not an edit";
}

TEST_F(Panel, ASliderScrubIsOneUndoStep) {
  doc->addNode("TetMesh", {}, "mesh");
  panel->setNode("mesh");
  QSlider* slider = child<QSlider>("quality");
  const int steps = doc->undoStack()->count();
  slider->setSliderDown(true);
  for (int v : {300, 400, 500, 600}) slider->setValue(v);
  slider->setSliderDown(false);
  EXPECT_EQ(doc->undoStack()->count(), steps + 1);
  EXPECT_DOUBLE_EQ(std::get<double>(doc->graph().param("mesh", "quality")), 6.0);
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>("quality")->value(), 6.0);
  slider->setSliderDown(true);
  slider->setValue(700);
  slider->setSliderDown(false);
  EXPECT_EQ(doc->undoStack()->count(), steps + 2) << "a new scrub is a new step";
}

TEST_F(Panel, ExpressionsAreValidatedAsTypedAndOnlyValidTextIsCommitted) {
  doc->addNode("FieldExpression", {}, "e");
  panel->setNode("e");
  QLineEdit* line = child<QLineEdit>("xy");
  ASSERT_NE(line, nullptr);
  line->setText("x * * y");
  emit line->textEdited(line->text());
  EXPECT_FALSE(panel->editor("xy")->error().isEmpty());
  emit line->editingFinished();
  EXPECT_EQ(doc->graph().param("e", "xy"), graph::ParamValue(std::string("y")));
  line->setText("sin(x) * y");
  emit line->textEdited(line->text());
  EXPECT_TRUE(panel->editor("xy")->error().isEmpty()) << panel->editor("xy")->error().toStdString();
  emit line->editingFinished();
  EXPECT_EQ(doc->graph().param("e", "xy"), graph::ParamValue(std::string("sin(x) * y")));
}

TEST_F(Panel, PointListsAreAnEditableTable) {
  doc->addNode("CurveConstraint", {}, "c");
  panel->setNode("c");
  auto* editor = dynamic_cast<PointListEditor*>(panel->editor("points"));
  ASSERT_NE(editor, nullptr);
  QTableWidget* table = editor->table();
  ASSERT_EQ(table->rowCount(), 3);
  table->item(1, 1)->setText("0.5");
  auto points = std::get<std::vector<graph::Vec3Param>>(doc->graph().param("c", "points"));
  EXPECT_EQ(points[1], (graph::Vec3Param{0, 0.5, 0}));
  table->setCurrentCell(0, 0);
  editor->addRow();  // half way between rows 0 and 1
  points = std::get<std::vector<graph::Vec3Param>>(doc->graph().param("c", "points"));
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1], (graph::Vec3Param{-0.25, 0.25, 0}));
  EXPECT_EQ(table->rowCount(), 4);
  // Removing below the declared minimum (2 points) is refused and shown.
  table->clearSelection();
  table->selectAll();
  editor->removeSelectedRows();
  EXPECT_FALSE(editor->error().isEmpty());
  EXPECT_EQ(std::get<std::vector<graph::Vec3Param>>(doc->graph().param("c", "points")).size(), 4u);
}

TEST_F(Panel, FollowsTheDocument) {
  doc->addNode("Propagate", {}, "f");
  panel->setNode("f");
  doc->setParam("f", "tolerance", 1e-5);
  EXPECT_DOUBLE_EQ(child<QDoubleSpinBox>("tolerance")->value(), 1e-5);
  EXPECT_EQ(child<QDoubleSpinBox>("tolerance")->text(), "1e-05");
  doc->remove({"f"});
  EXPECT_EQ(panel->node(), "");
  EXPECT_EQ(panel->editor("tolerance"), nullptr);
}

}  // namespace
}  // namespace tfd::ui
