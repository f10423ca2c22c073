#pragma once
// The node canvas: a QGraphicsScene mirroring the document (items are rebuilt from it on every
// change; the document stays the single source of truth). Mouse work: drag from a port to link
// (only type-compatible ports light up; a link dropped on empty space asks for a node type),
// pick up a link from a single input to move or remove it, click the display flag, drag nodes
// (committed as one undo step when the drag ends), box select (the view's rubber band).
#include <QGraphicsScene>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ui/canvas/node_item.h"
#include "ui/cook/node_status.h"
#include "ui/document/graph_document.h"

namespace tfd::ui {

class LinkItem;

/// Where a link being dragged starts: a port and which side it is.
struct LinkStart {
  graph::Endpoint endpoint;
  bool isOutput = true;
  const graph::ValueType* type = nullptr;
};

class CanvasScene : public QGraphicsScene {
  Q_OBJECT

 public:
  explicit CanvasScene(GraphDocument& document, QObject* parent = nullptr);
  ~CanvasScene() override;

  GraphDocument& document() { return document_; }
  NodeItem* nodeItem(std::string_view name) const;
  std::vector<NodeItem*> nodeItems() const;
  std::vector<LinkItem*> linkItems() const { return links_; }

  /// Selected node names in document order; selected links.
  std::vector<std::string> selectedNodeNames() const;
  std::vector<graph::Link> selectedLinks() const;
  void selectNodes(const std::vector<std::string>& names);
  /// Removes the selected nodes and links as one undo step.
  bool deleteSelection();
  /// Bounding rectangle of the (selected) nodes; empty when there are none.
  QRectF nodesRect(bool selectedOnly) const;

  void setStatuses(const NodeStatusMap& statuses);
  void setStatus(const std::string& node, const NodeStatus& status);

  // ---- dragging a link (the mouse handlers use these; so can scripts and tests)
  /// Starts at a port. From a linked single input, the link is picked up (its output end stays).
  bool beginLinkDrag(const std::string& node, PortRef port);
  void moveLinkDrag(QPointF scenePos);
  /// Ends the drag at a scene position: links to a compatible port there; on empty space emits
  /// linkDroppedOnEmpty (a picked-up link is removed). Returns true when the document changed.
  bool endLinkDrag(QPointF scenePos, QPoint screenPos = {});
  bool linkDragActive() const { return drag_.has_value(); }
  /// The ports lit during the drag: (node, port).
  std::vector<std::pair<std::string, PortRef>> highlightedPorts() const;

 signals:
  void selectedNodesChanged();
  void linkDroppedOnEmpty(QPointF scenePos, QPoint screenPos, tfd::ui::LinkStart start);

 protected:
  void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
  void mouseMoveEvent(QGraphicsSceneMouseEvent* event) override;
  void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;

 private:
  struct Drag {
    LinkStart start;
    std::optional<graph::Link> pickedUp;
    QGraphicsPathItem* preview = nullptr;
  };
  void sync(int flags);
  void rebuildLinks();
  void commitMoves();
  void highlightCompatible();
  void clearHighlights();
  /// The node and port under a scene position, over every node (ports stick out of the body).
  std::optional<std::pair<NodeItem*, PortRef>> portAt(QPointF scenePos) const;
  bool compatible(const LinkStart& start, const std::string& node, PortRef port) const;

  GraphDocument& document_;
  std::map<std::string, NodeItem*, std::less<>> nodes_;
  std::vector<LinkItem*> links_;
  NodeStatusMap statuses_;
  std::optional<Drag> drag_;
  bool movingNodes_ = false;
};

}  // namespace tfd::ui
