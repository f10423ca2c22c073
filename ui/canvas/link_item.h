#pragma once
// A link on the canvas: a horizontal cubic curve from an output port to an input port, in the
// colour of its value type. Selectable (Delete removes it).
#include <QGraphicsPathItem>

#include "graph/graph.h"
#include "ui/canvas/node_item.h"

namespace tfd::ui {

/// The curve between two scene points (shared with the link being dragged).
QPainterPath linkPath(QPointF from, QPointF to);

class LinkItem : public QGraphicsPathItem {
 public:
  enum { Type = UserType + 2 };
  LinkItem(graph::Link link, NodeItem* from, PortRef fromPort, NodeItem* to, PortRef toPort);
  ~LinkItem() override;

  int type() const override { return Type; }
  const graph::Link& link() const { return link_; }
  void updatePath();
  /// Forgets the nodes (they are being deleted with the scene).
  void detach();
  QPainterPath shape() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  graph::Link link_;
  NodeItem* from_;
  PortRef fromPort_;
  NodeItem* to_;
  PortRef toPort_;
  QColor colour_;
};

}  // namespace tfd::ui
