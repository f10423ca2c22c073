#pragma once
// A list of points ([[x, y, z], ...]) as an editable table: edit cells, add a row (after the
// selected one, half way to the next point, or past the last one), remove rows. Each change is
// one undo step; a list shorter than the declaration allows is refused and shown as an error.
// Points can also be added by clicking in the viewport (main window).
#include "ui/params/param_editor.h"

class QTableWidget;

namespace tfd::ui {

class PointListEditor : public ParamEditor {
 public:
  PointListEditor(const graph::ParamDecl& decl, QWidget* parent);
  void setValue(const graph::ParamValue& value) override;
  QTableWidget* table() const { return table_; }
  /// The points as shown in the table.
  std::vector<graph::Vec3Param> points() const;
  void addRow();
  void removeSelectedRows();

 private:
  void commit(std::vector<graph::Vec3Param> points);

  QTableWidget* table_;
  bool filling_ = false;
};

}  // namespace tfd::ui
