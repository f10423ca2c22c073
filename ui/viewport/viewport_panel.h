#pragma once
// The viewport with its tool bar: it draws the display-flag node's last cooked output
// (display_scene.h), a cutting plane by quantity along an axis, and the selected node's region
// and picks; a click picks for the selected node (picking.h). The document and the cook
// controller are the sources: nothing here holds graph data beyond the scene it draws.
#include <QWidget>

#include <optional>
#include <string>

#include "render/scene_builder.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/viewport/viewport_widget.h"

class QComboBox;
class QLabel;
class QSlider;

namespace tfd::ui {

class ViewportPanel : public QWidget {
  Q_OBJECT

 public:
  ViewportPanel(GraphDocument& document, CookController& cook, QWidget* parent = nullptr);

  ViewportWidget* view() const { return view_; }
  /// The node whose parameters a click fills (the canvas selection); "" for none.
  void setSelectedNode(const std::string& node);
  const std::string& selectedNode() const { return selected_; }
  /// The cutting plane (nothing: off).
  std::optional<render::SliceSettings> slice() const;
  void setSlice(const std::optional<render::SliceSettings>& slice);
  /// What a left click at a pixel does (public for scripts and tests). True when the document
  /// changed.
  bool clickAt(QPointF pixel);
  /// The node the viewport shows ("" when nothing has cooked for it).
  const std::string& shownNode() const { return shown_; }

 signals:
  /// A short message for the status bar (pick results, why a click did nothing).
  void message(const QString& text);

 private:
  void rebuildBase();
  void rebuildOverlay();
  void updateHint();

  GraphDocument& document_;
  CookController& cook_;
  ViewportWidget* view_;
  QComboBox* quantity_;
  QComboBox* axis_;
  QSlider* position_;
  QLabel* hint_;
  render::Scene base_;
  std::string selected_, shown_;
  bool framedOnce_ = false;
};

}  // namespace tfd::ui
