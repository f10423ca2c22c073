#pragma once
// One parameter's editing widget, made from its declaration (param_editors.cpp). An editor
// shows a value (setValue never reports an edit) and reports the user's edits through onEdit:
// `continuous` edits (a slider being dragged) merge into one undo step until onFinish.
// Text that does not pass the declaration's checks is marked as you type and not committed.
#include <QWidget>

#include <functional>
#include <memory>

#include "graph/param.h"

namespace tfd::ui {

class ParamEditor : public QWidget {
 public:
  explicit ParamEditor(const graph::ParamDecl& decl, QWidget* parent = nullptr)
      : QWidget(parent), decl_(decl) {}

  const graph::ParamDecl& decl() const { return decl_; }
  /// Shows a value without reporting an edit.
  virtual void setValue(const graph::ParamValue& value) = 0;
  /// Marks the editor invalid with a reason (empty: valid again).
  void setError(const QString& message);
  const QString& error() const { return error_; }

  std::function<void(graph::ParamValue value, bool continuous)> onEdit;
  std::function<void()> onFinish;

 protected:
  void edit(graph::ParamValue value, bool continuous = false) {
    if (onEdit) onEdit(std::move(value), continuous);
  }
  void finish() {
    if (onFinish) onFinish();
  }
  /// checkParamValue as a message: "" when valid.
  QString problemWith(const graph::ParamValue& value) const;

 private:
  const graph::ParamDecl& decl_;
  QString error_;
};

/// The editor for a declaration: check box, spin box (+ slider within a range), combo box,
/// text (validated), file field with a picker, vec3, fixed-size number list, point table.
std::unique_ptr<ParamEditor> makeParamEditor(const graph::ParamDecl& decl, QWidget* parent);

}  // namespace tfd::ui
