#include "ui/canvas/link_item.h"

#include <QPainter>
#include <QPainterPathStroker>

#include <algorithm>
#include <cmath>

#include "ui/canvas/canvas_style.h"

namespace tfd::ui {

QPainterPath linkPath(QPointF from, QPointF to) {
  QPainterPath path(from);
  const double dx = std::max(40.0, std::abs(to.x() - from.x()) * 0.5);
  path.cubicTo(from + QPointF(dx, 0), to - QPointF(dx, 0), to);
  return path;
}

LinkItem::LinkItem(graph::Link link, NodeItem* from, PortRef fromPort, NodeItem* to, PortRef toPort)
    : link_(std::move(link)), from_(from), fromPort_(fromPort), to_(to), toPort_(toPort) {
  setFlag(ItemIsSelectable);
  setZValue(0);
  colour_ = style::valueTypeColour(from->portDecl(fromPort).type->name);
  from_->addLink(this);
  to_->addLink(this);
  setToolTip(QString::fromStdString(link_.from.str() + " → " + link_.to.str()));
  updatePath();
}

LinkItem::~LinkItem() {
  if (from_) from_->removeLink(this);
  if (to_) to_->removeLink(this);
}

void LinkItem::detach() { from_ = to_ = nullptr; }

void LinkItem::updatePath() {
  if (from_ && to_) setPath(linkPath(from_->portScenePos(fromPort_), to_->portScenePos(toPort_)));
}

QPainterPath LinkItem::shape() const {
  QPainterPathStroker s;
  s.setWidth(10);
  return s.createStroke(path());
}

void LinkItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  p->setPen(QPen(isSelected() ? style::nodeSelected() : colour_, isSelected() ? 3.5 : 2.2));
  p->drawPath(path());
}

}  // namespace tfd::ui
