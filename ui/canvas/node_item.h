#pragma once
// A node on the canvas: header with the name, the display flag at the left edge, the status
// badge at the right, input ports on the left and output ports on the right (from the node
// type's declaration), the cook time below. It mirrors the document; dragging moves the item,
// and the scene commits the new positions to the document as one undo step when the drag ends.
#include <QGraphicsItem>

#include <optional>
#include <string>
#include <vector>

#include "graph/graph.h"
#include "ui/cook/node_status.h"

namespace tfd::ui {

class LinkItem;

/// A port of a node: an input or an output, by declaration index.
struct PortRef {
  bool output = false;
  int index = 0;
  bool operator==(const PortRef&) const = default;
};

class NodeItem : public QGraphicsItem {
 public:
  enum { Type = UserType + 1 };
  explicit NodeItem(const graph::Node& node);

  int type() const override { return Type; }
  const std::string& name() const { return name_; }
  const graph::NodeDecl& decl() const { return *decl_; }
  /// Refreshes name, display flag and position (unless the item is being dragged).
  void updateFrom(const graph::Node& node, bool moveToDocumentPosition);

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

  QPointF portScenePos(PortRef port) const;
  /// The port under a scene position (within a few pixels), if any.
  std::optional<PortRef> portAt(QPointF scenePos) const;
  const graph::PortDecl& portDecl(PortRef port) const;
  std::string portName(PortRef port) const { return portDecl(port).name; }
  /// True when the scene position is on the display-flag strip.
  bool displayFlagAt(QPointF scenePos) const;

  void setStatus(const NodeStatus& status);
  const NodeStatus& status() const { return status_; }
  bool displayFlag() const { return display_; }
  /// Ports that would accept the link being dragged (drawn highlighted).
  void setHighlightedPorts(std::vector<PortRef> ports);
  const std::vector<PortRef>& highlightedPorts() const { return highlighted_; }

  void addLink(LinkItem* link) { links_.push_back(link); }
  void removeLink(LinkItem* link);

 protected:
  QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

 private:
  double height() const;
  void paintPorts(QPainter* p) const;
  void paintBadge(QPainter* p) const;
  void refreshToolTip();

  std::string name_;
  const graph::NodeDecl* decl_;
  bool display_ = false;
  NodeStatus status_;
  std::vector<PortRef> highlighted_;
  std::vector<LinkItem*> links_;
};

}  // namespace tfd::ui
