#pragma once
// The view of the node canvas: wheel zoom about the cursor, middle-button (or Alt+left) pan,
// rubber-band box selection, Tab for the node menu at the cursor, F to frame the selection (or
// everything), A or Home to frame everything, Delete/Backspace to delete the selection.
#include <QGraphicsView>

#include <optional>

#include "ui/canvas/canvas_scene.h"

namespace tfd::ui {

class NodeMenu;

class CanvasView : public QGraphicsView {
  Q_OBJECT

 public:
  explicit CanvasView(CanvasScene* scene, QWidget* parent = nullptr);

  CanvasScene* canvas() const { return scene_; }
  NodeMenu* nodeMenu() const { return menu_; }
  void frameAll();
  void frameSelection();
  /// Current scale (1 = one scene unit per pixel).
  double zoom() const { return transform().m11(); }
  /// Zooms by `factor` keeping the scene point under `viewPos` in place (clamped to 0.1 - 4).
  void zoomBy(double factor, QPoint viewPos);
  /// Opens the node menu at a view position; a chosen type is added there (linked to `link`).
  void openNodeMenu(QPoint viewPos, std::optional<LinkStart> link = std::nullopt);

 protected:
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  bool focusNextPrevChild(bool next) override;
  void drawBackground(QPainter* painter, const QRectF& rect) override;

 private:
  void frame(QRectF rect);

  CanvasScene* scene_;
  NodeMenu* menu_;
  QPointF menuScenePos_;
  std::optional<LinkStart> menuLink_;
  std::optional<QPoint> panFrom_;
};

}  // namespace tfd::ui
