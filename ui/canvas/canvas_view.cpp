#include "ui/canvas/canvas_view.h"

#include <QKeyEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/node_menu.h"

namespace tfd::ui {

CanvasView::CanvasView(CanvasScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent), scene_(scene) {
  setRenderHint(QPainter::Antialiasing);
  setDragMode(QGraphicsView::RubberBandDrag);
  setRubberBandSelectionMode(Qt::IntersectsItemShape);
  setTransformationAnchor(QGraphicsView::NoAnchor);
  setViewportUpdateMode(QGraphicsView::SmartViewportUpdate);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setFocusPolicy(Qt::StrongFocus);
  menu_ = new NodeMenu(scene->document().registry(), this);
  connect(menu_, &NodeMenu::typeChosen, this, [this](const QString& type) {
    GraphDocument& doc = scene_->document();
    std::string added;
    const std::string t = type.toStdString();
    QPointF at = menuScenePos_;
    if (menuLink_) {
      if (!menuLink_->isOutput) at -= QPointF(style::kNodeWidth, 0);
      added = doc.addNodeLinked(t, at, menuLink_->endpoint, menuLink_->isOutput);
    } else {
      added = doc.addNode(t, at);
    }
    if (!added.empty()) scene_->selectNodes({added});
  });
  connect(scene, &CanvasScene::linkDroppedOnEmpty, this,
          [this](QPointF scenePos, QPoint, LinkStart start) {
            openNodeMenu(mapFromScene(scenePos), start);
          });
}

void CanvasView::frame(QRectF rect) {
  if (rect.isEmpty()) return;
  rect.adjust(-40, -40, 40, 40);
  fitInView(rect, Qt::KeepAspectRatio);
  const double s = zoom();
  if (s > 1.5) scale(1.5 / s, 1.5 / s);
  centerOn(rect.center());
}

void CanvasView::frameAll() { frame(scene_->nodesRect(false)); }

void CanvasView::frameSelection() {
  const QRectF r = scene_->nodesRect(true);
  frame(r.isEmpty() ? scene_->nodesRect(false) : r);
}

void CanvasView::zoomBy(double factor, QPoint viewPos) {
  const double target = std::clamp(zoom() * factor, 0.1, 4.0);
  factor = target / zoom();
  const QPointF before = mapToScene(viewPos);
  scale(factor, factor);
  const QPointF after = mapToScene(viewPos);
  centerOn(mapToScene(viewport()->rect().center()) + (before - after));
}

void CanvasView::openNodeMenu(QPoint viewPos, std::optional<LinkStart> link) {
  menuScenePos_ = mapToScene(viewPos);
  menuLink_ = link;
  menu_->setLinkFilter(link);
  menu_->popupAt(viewport()->mapToGlobal(viewPos));
}

void CanvasView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  zoomBy(std::pow(1.15, steps), event->position().toPoint());
  event->accept();
}

void CanvasView::mousePressEvent(QMouseEvent* event) {
  const bool pan = event->button() == Qt::MiddleButton ||
                   (event->button() == Qt::LeftButton && (event->modifiers() & Qt::AltModifier));
  if (pan) {
    panFrom_ = event->pos();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  QGraphicsView::mousePressEvent(event);
}

void CanvasView::mouseMoveEvent(QMouseEvent* event) {
  if (panFrom_) {
    const QPoint d = event->pos() - *panFrom_;
    panFrom_ = event->pos();
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() - d.y());
    event->accept();
    return;
  }
  QGraphicsView::mouseMoveEvent(event);
}

void CanvasView::mouseReleaseEvent(QMouseEvent* event) {
  if (panFrom_) {
    panFrom_.reset();
    unsetCursor();
    event->accept();
    return;
  }
  QGraphicsView::mouseReleaseEvent(event);
}

bool CanvasView::focusNextPrevChild(bool) { return false; }  // Tab opens the node menu

void CanvasView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Tab: {
      QPoint at = mapFromGlobal(QCursor::pos());
      if (!viewport()->rect().contains(at)) at = viewport()->rect().center();
      openNodeMenu(at);
      return;
    }
    case Qt::Key_F:
      frameSelection();
      return;
    case Qt::Key_A:
    case Qt::Key_Home:
      frameAll();
      return;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
      scene_->deleteSelection();
      return;
    default:
      break;
  }
  QGraphicsView::keyPressEvent(event);
}

void CanvasView::drawBackground(QPainter* painter, const QRectF& rect) {
  QGraphicsView::drawBackground(painter, rect);
  if (zoom() < 0.3) return;
  const double step = 40;
  painter->setPen(QPen(style::canvasBackground().lighter(118), 0));
  const double left = std::floor(rect.left() / step) * step;
  const double top = std::floor(rect.top() / step) * step;
  QVector<QLineF> lines;
  for (double x = left; x < rect.right(); x += step)
    lines.append(QLineF(x, rect.top(), x, rect.bottom()));
  for (double y = top; y < rect.bottom(); y += step)
    lines.append(QLineF(rect.left(), y, rect.right(), y));
  painter->drawLines(lines);
}

}  // namespace tfd::ui
