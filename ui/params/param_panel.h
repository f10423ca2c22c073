#pragma once
// The parameter panel of the selected node, generated from its type's declaration: a row per
// parameter with its label, an editor (param_editor.h), a reset button when the value differs
// from the default, and the documentation as tooltip. Edits go to the document as undoable
// commands; the panel refreshes from the document on every change (undo included), so it never
// holds values of its own.
#include <QWidget>

#include <map>
#include <string>

#include "ui/document/graph_document.h"
#include "ui/params/param_editor.h"

class QFormLayout;
class QLabel;
class QToolButton;

namespace tfd::ui {

class ParamPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ParamPanel(GraphDocument& document, QWidget* parent = nullptr);

  /// Shows the node's parameters ("" for none).
  void setNode(const std::string& node);
  const std::string& node() const { return node_; }
  /// The editor of a parameter of the shown node (for scripts and tests).
  ParamEditor* editor(const std::string& param) const;

 private:
  void rebuild();
  void refresh();

  GraphDocument& document_;
  std::string node_;
  const graph::NodeDecl* decl_ = nullptr;
  QLabel* title_;
  QLabel* doc_;
  QWidget* form_ = nullptr;
  std::map<std::string, ParamEditor*> editors_;
  std::map<std::string, QToolButton*> resets_;
};

}  // namespace tfd::ui
