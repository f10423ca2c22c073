#include "ui/canvas/canvas_scene.h"

#include <QGraphicsSceneMouseEvent>
#include <QGraphicsView>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <set>

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/link_item.h"
#include "ui/document/node_ui.h"

namespace tfd::ui {

CanvasScene::CanvasScene(GraphDocument& document, QObject* parent)
    : QGraphicsScene(parent), document_(document) {
  setBackgroundBrush(style::canvasBackground());
  setSceneRect(-20000, -20000, 40000, 40000);
  connect(&document_, &GraphDocument::changed, this, &CanvasScene::sync);
  connect(this, &QGraphicsScene::selectionChanged, this, &CanvasScene::selectedNodesChanged);
  sync(kDocumentReplaced | kStructureChanged);
}

CanvasScene::~CanvasScene() {
  // ~QGraphicsScene deselects the items it deletes and emits selectionChanged when this is a
  // CanvasScene no more: calling our signal then is undefined (UBSan, editor_gl test).
  disconnect(this, &QGraphicsScene::selectionChanged, this, &CanvasScene::selectedNodesChanged);
  for (LinkItem* l : links_) l->detach();
}

NodeItem* CanvasScene::nodeItem(std::string_view name) const {
  auto it = nodes_.find(name);
  return it == nodes_.end() ? nullptr : it->second;
}

std::vector<NodeItem*> CanvasScene::nodeItems() const {
  std::vector<NodeItem*> out;
  for (const graph::Node& n : document_.graph().nodes())
    if (NodeItem* item = nodeItem(n.name())) out.push_back(item);
  return out;
}

void CanvasScene::sync(int flags) {
  const graph::Graph& g = document_.graph();
  if (flags & (kStructureChanged | kDocumentReplaced)) {
    std::set<std::string, std::less<>> names;
    for (const graph::Node& n : g.nodes()) names.insert(n.name());
    std::vector<std::string> stale;
    for (const auto& [name, item] : nodes_)
      if (!names.count(name) || &g.node(name).decl() != &item->decl()) stale.push_back(name);
    if (!stale.empty()) {
      for (LinkItem* l : links_) delete l;  // while both of its nodes still exist
      links_.clear();
      for (const std::string& name : stale) {
        delete nodes_[name];
        nodes_.erase(name);
      }
    }
    for (const graph::Node& n : g.nodes())
      if (!nodes_.count(n.name())) {
        auto* item = new NodeItem(n);
        addItem(item);
        nodes_[n.name()] = item;
        if (auto s = statuses_.find(n.name()); s != statuses_.end()) item->setStatus(s->second);
      }
    rebuildLinks();
  }
  for (const graph::Node& n : g.nodes())
    if (NodeItem* item = nodeItem(n.name())) item->updateFrom(n, !movingNodes_);
}

void CanvasScene::rebuildLinks() {
  std::vector<graph::Link> selected = selectedLinks();
  for (LinkItem* l : links_) delete l;
  links_.clear();
  for (const graph::Link& l : document_.graph().links()) {
    NodeItem* a = nodeItem(l.from.node);
    NodeItem* b = nodeItem(l.to.node);
    if (!a || !b) continue;
    auto* item = new LinkItem(l, a, {true, a->decl().outputIndex(l.from.port)}, b,
                              {false, b->decl().inputIndex(l.to.port)});
    addItem(item);
    if (std::find(selected.begin(), selected.end(), l) != selected.end()) item->setSelected(true);
    links_.push_back(item);
  }
}

std::vector<std::string> CanvasScene::selectedNodeNames() const {
  std::vector<std::string> out;
  for (NodeItem* item : nodeItems())
    if (item->isSelected()) out.push_back(item->name());
  return out;
}

std::vector<graph::Link> CanvasScene::selectedLinks() const {
  std::vector<graph::Link> out;
  for (LinkItem* l : links_)
    if (l->isSelected()) out.push_back(l->link());
  return out;
}

void CanvasScene::selectNodes(const std::vector<std::string>& names) {
  {
    const QSignalBlocker block(this);  // one notification for the whole change, below
    clearSelection();
    for (const std::string& n : names)
      if (NodeItem* item = nodeItem(n)) item->setSelected(true);
  }
  emit selectedNodesChanged();
}

bool CanvasScene::deleteSelection() {
  std::vector<std::string> nodes = selectedNodeNames();
  std::vector<graph::Link> links;
  for (const graph::Link& l : selectedLinks())
    if (std::find(nodes.begin(), nodes.end(), l.from.node) == nodes.end() &&
        std::find(nodes.begin(), nodes.end(), l.to.node) == nodes.end())
      links.push_back(l);
  return document_.remove(nodes, links);
}

QRectF CanvasScene::nodesRect(bool selectedOnly) const {
  QRectF r;
  for (NodeItem* item : nodeItems())
    if (!selectedOnly || item->isSelected()) r |= item->sceneBoundingRect();
  return r;
}

void CanvasScene::setStatuses(const NodeStatusMap& statuses) {
  statuses_ = statuses;
  for (auto& [name, item] : nodes_) {
    auto it = statuses_.find(name);
    item->setStatus(it == statuses_.end() ? NodeStatus{} : it->second);
  }
}

void CanvasScene::setStatus(const std::string& node, const NodeStatus& status) {
  statuses_[node] = status;
  if (NodeItem* item = nodeItem(node)) item->setStatus(status);
}

// ---- link dragging

bool CanvasScene::compatible(const LinkStart& start, const std::string& node, PortRef port) const {
  if (port.output == start.isOutput || node == start.endpoint.node) return false;
  NodeItem* item = nodeItem(node);
  if (!item || item->portDecl(port).type != start.type) return false;
  const graph::Endpoint other{node, item->portName(port)};
  return start.isOutput ? document_.canConnect(start.endpoint, other)
                        : document_.canConnect(other, start.endpoint);
}

bool CanvasScene::beginLinkDrag(const std::string& node, PortRef port) {
  NodeItem* item = nodeItem(node);
  if (!item) return false;
  Drag d;
  d.start = {{node, item->portName(port)}, port.output, item->portDecl(port).type};
  if (!port.output && !item->portDecl(port).multiple) {
    auto in = document_.graph().linksInto(node, d.start.endpoint.port);
    if (!in.empty()) {  // pick up the link: drag its output end's link anew
      d.pickedUp = in.front();
      d.start = {in.front().from, true, d.start.type};
    }
  }
  d.preview =
      addPath(QPainterPath(), QPen(style::valueTypeColour(d.start.type->name), 2, Qt::DashLine));
  d.preview->setZValue(3);
  drag_ = std::move(d);
  highlightCompatible();
  return true;
}

void CanvasScene::highlightCompatible() {
  for (NodeItem* item : nodeItems()) {
    std::vector<PortRef> lit;
    const auto& decl = item->decl();
    for (bool output : {false, true}) {
      const int n = static_cast<int>(output ? decl.outputs().size() : decl.inputs().size());
      for (int i = 0; i < n; ++i) {
        PortRef p{output, i};
        const bool sameAsPickedUp = drag_->pickedUp && !output &&
                                    item->name() == drag_->pickedUp->to.node &&
                                    item->portName(p) == drag_->pickedUp->to.port;
        if (sameAsPickedUp || compatible(drag_->start, item->name(), p)) lit.push_back(p);
      }
    }
    item->setHighlightedPorts(std::move(lit));
  }
}

void CanvasScene::clearHighlights() {
  for (NodeItem* item : nodeItems()) item->setHighlightedPorts({});
}

std::vector<std::pair<std::string, PortRef>> CanvasScene::highlightedPorts() const {
  std::vector<std::pair<std::string, PortRef>> out;
  for (NodeItem* item : nodeItems())
    for (PortRef p : item->highlightedPorts()) out.emplace_back(item->name(), p);
  return out;
}

void CanvasScene::moveLinkDrag(QPointF scenePos) {
  if (!drag_) return;
  NodeItem* item = nodeItem(drag_->start.endpoint.node);
  if (!item) return;
  const auto& decl = item->decl();
  const int index = drag_->start.isOutput ? decl.outputIndex(drag_->start.endpoint.port)
                                          : decl.inputIndex(drag_->start.endpoint.port);
  const QPointF anchor = item->portScenePos({drag_->start.isOutput, index});
  drag_->preview->setPath(drag_->start.isOutput ? linkPath(anchor, scenePos)
                                                : linkPath(scenePos, anchor));
}

std::optional<std::pair<NodeItem*, PortRef>> CanvasScene::portAt(QPointF scenePos) const {
  for (NodeItem* item : nodeItems())
    if (auto p = item->portAt(scenePos)) return std::make_pair(item, *p);
  return std::nullopt;
}

bool CanvasScene::endLinkDrag(QPointF scenePos, QPoint screenPos) {
  if (!drag_) return false;
  Drag d = std::move(*drag_);
  drag_.reset();
  delete d.preview;
  std::vector<std::pair<std::string, PortRef>> lit = highlightedPorts();
  clearHighlights();
  auto hit = portAt(scenePos);
  if (hit) {
    const std::pair<std::string, PortRef> key{hit->first->name(), hit->second};
    if (std::find(lit.begin(), lit.end(), key) == lit.end()) return false;  // not compatible
    const graph::Endpoint other{hit->first->name(), hit->first->portName(hit->second)};
    if (d.pickedUp) return document_.relink(*d.pickedUp, other);
    return d.start.isOutput ? document_.connect(d.start.endpoint, other)
                            : document_.connect(other, d.start.endpoint);
  }
  if (itemAt(scenePos, QTransform())) return false;  // dropped on a node body: nothing
  bool changed = false;
  if (d.pickedUp) changed = document_.relink(*d.pickedUp, std::nullopt);
  if (!d.pickedUp) emit linkDroppedOnEmpty(scenePos, screenPos, d.start);
  return changed;
}

// ---- mouse

void CanvasScene::mousePressEvent(QGraphicsSceneMouseEvent* event) {
  if (event->button() == Qt::LeftButton) {
    if (auto hit = portAt(event->scenePos())) {
      beginLinkDrag(hit->first->name(), hit->second);
      moveLinkDrag(event->scenePos());
      event->accept();
      return;
    }
    for (NodeItem* item : nodeItems())
      if (item->displayFlagAt(event->scenePos())) {
        document_.setDisplayNode(item->displayFlag() ? "" : item->name());
        event->accept();
        return;
      }
  }
  QGraphicsScene::mousePressEvent(event);
  movingNodes_ = event->button() == Qt::LeftButton;
}

void CanvasScene::mouseMoveEvent(QGraphicsSceneMouseEvent* event) {
  if (drag_) {
    moveLinkDrag(event->scenePos());
    event->accept();
    return;
  }
  QGraphicsScene::mouseMoveEvent(event);
}

void CanvasScene::mouseReleaseEvent(QGraphicsSceneMouseEvent* event) {
  if (drag_) {
    endLinkDrag(event->scenePos(), event->screenPos());
    event->accept();
    return;
  }
  QGraphicsScene::mouseReleaseEvent(event);
  if (movingNodes_) {
    movingNodes_ = false;
    commitMoves();
  }
}

void CanvasScene::commitMoves() {
  std::map<std::string, QPointF> moved;
  for (NodeItem* item : nodeItems()) {
    const graph::Node& n = document_.graph().node(item->name());
    const QPointF p(std::round(item->pos().x()), std::round(item->pos().y()));
    if (p != nodePosition(n)) moved[item->name()] = p;
  }
  if (!moved.empty()) document_.moveNodes(moved);
}

}  // namespace tfd::ui
