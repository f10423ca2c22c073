#include "ui/canvas/node_item.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>
#include <cmath>

#include "nodes/display_values.h"
#include "ui/canvas/canvas_style.h"
#include "ui/canvas/link_item.h"
#include "ui/document/node_ui.h"

namespace tfd::ui {

namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

QString formatSeconds(double s) {
  if (s < 1e-3) return QString("%1 µs").arg(s * 1e6, 0, 'f', 0);
  if (s < 1) return QString("%1 ms").arg(s * 1e3, 0, 'f', 1);
  return QString("%1 s").arg(s, 0, 'f', 2);
}

}  // namespace

NodeItem::NodeItem(const graph::Node& node) : name_(node.name()), decl_(&node.decl()) {
  setFlags(ItemIsSelectable | ItemIsMovable | ItemSendsGeometryChanges);
  setZValue(1);
  updateFrom(node, true);
}

void NodeItem::updateFrom(const graph::Node& node, bool moveToDocumentPosition) {
  if (name_ != node.name()) name_ = node.name();
  const bool display = nodes::hasDisplayFlag(node);
  if (display != display_) {
    display_ = display;
    update();
  }
  if (moveToDocumentPosition && pos() != nodePosition(node)) setPos(nodePosition(node));
  refreshToolTip();
  update();
}

double NodeItem::height() const {
  const auto rows = std::max(decl_->inputs().size(), decl_->outputs().size());
  return style::kHeaderHeight + std::max<double>(1, rows) * style::kRowHeight + 6;
}

QRectF NodeItem::boundingRect() const {
  // Room for port circles outside the body, the badge and the cook-time line below.
  const double m = style::kPortHitRadius;
  return QRectF(-m, -m, style::kNodeWidth + 2 * m, height() + 2 * m + 16);
}

QPointF NodeItem::portScenePos(PortRef port) const {
  const double y = style::kHeaderHeight + (port.index + 0.5) * style::kRowHeight;
  return mapToScene(QPointF(port.output ? style::kNodeWidth : 0, y));
}

const graph::PortDecl& NodeItem::portDecl(PortRef port) const {
  return port.output ? decl_->outputs()[port.index] : decl_->inputs()[port.index];
}

std::optional<PortRef> NodeItem::portAt(QPointF scenePos) const {
  for (bool output : {false, true}) {
    const int n = static_cast<int>(output ? decl_->outputs().size() : decl_->inputs().size());
    for (int i = 0; i < n; ++i) {
      const QPointF d = portScenePos({output, i}) - scenePos;
      if (std::hypot(d.x(), d.y()) <= style::kPortHitRadius) return PortRef{output, i};
    }
  }
  return std::nullopt;
}

bool NodeItem::displayFlagAt(QPointF scenePos) const {
  const QPointF p = mapFromScene(scenePos);
  return p.x() >= 0 && p.x() <= style::kDisplayFlagWidth && p.y() >= 0 &&
         p.y() <= style::kHeaderHeight;
}

void NodeItem::setStatus(const NodeStatus& status) {
  status_ = status;
  refreshToolTip();
  update();
}

void NodeItem::setHighlightedPorts(std::vector<PortRef> ports) {
  highlighted_ = std::move(ports);
  update();
}

void NodeItem::removeLink(LinkItem* link) { std::erase(links_, link); }

QVariant NodeItem::itemChange(GraphicsItemChange change, const QVariant& value) {
  if (change == ItemPositionHasChanged)
    for (LinkItem* l : links_) l->updatePath();
  return QGraphicsItem::itemChange(change, value);
}

void NodeItem::refreshToolTip() {
  QString tip = "<b>" + q(name_) + "</b> (" + q(decl_->typeName()) + ")";
  if (!decl_->doc().empty()) tip += "<br>" + q(decl_->doc()).toHtmlEscaped();
  tip += "<br><i>" + QString(stateLabel(status_.state)) + "</i>";
  if (status_.state == NodeStatus::State::UpstreamFailed && !status_.failedNode.empty())
    tip += " (node \"" + q(status_.failedNode) + "\" failed)";
  if (status_.seconds > 0) tip += ", " + formatSeconds(status_.seconds);
  for (const graph::NodeMessage& m : status_.messages) {
    const char* colour = m.severity == graph::Severity::Error     ? "#e22"
                         : m.severity == graph::Severity::Warning ? "#c90"
                                                                  : "#888";
    tip += QString("<br><span style='color:%1'>").arg(colour) +
           q(std::string(graph::severityName(m.severity)) + ": " + m.text).toHtmlEscaped() +
           "</span>";
  }
  setToolTip(tip);
}

void NodeItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  p->setRenderHint(QPainter::Antialiasing);
  const QRectF body(0, 0, style::kNodeWidth, height());
  QColor outline = isSelected() ? style::nodeSelected() : QColor(20, 20, 24);
  if (status_.state == NodeStatus::State::Failed) outline = style::errorRed();
  p->setPen(QPen(outline, isSelected() || status_.hasError() ? 2.5 : 1.2));
  p->setBrush(style::nodeBody());
  p->drawRoundedRect(body, 5, 5);
  // Header and display flag.
  p->setPen(Qt::NoPen);
  p->setBrush(status_.state == NodeStatus::State::UpstreamFailed
                  ? style::upstreamOrange().darker(160)
                  : style::nodeHeader());
  p->drawRoundedRect(QRectF(1, 1, style::kNodeWidth - 2, style::kHeaderHeight - 1), 4, 4);
  p->setBrush(display_ ? style::displayFlagOn() : style::displayFlagOff());
  p->drawRoundedRect(QRectF(1, 1, style::kDisplayFlagWidth, style::kHeaderHeight - 1), 4, 4);
  p->setPen(style::textColour());
  QFont f = p->font();
  f.setPointSizeF(9);
  f.setBold(true);
  p->setFont(f);
  const QRectF titleRect(style::kDisplayFlagWidth + 6, 0, style::kNodeWidth - 50,
                         style::kHeaderHeight);
  p->drawText(titleRect, Qt::AlignVCenter | Qt::AlignLeft,
              p->fontMetrics().elidedText(q(name_), Qt::ElideRight, int(titleRect.width())));
  paintPorts(p);
  paintBadge(p);
  // Type and cook time below the body.
  f.setBold(false);
  f.setPointSizeF(7.5);
  p->setFont(f);
  p->setPen(style::dimText());
  QString below = q(decl_->typeName());
  if (status_.seconds > 0 &&
      (status_.state == NodeStatus::State::Cooked || status_.state == NodeStatus::State::Cached))
    below += "  ·  " + formatSeconds(status_.seconds);
  p->drawText(QRectF(0, height() + 2, style::kNodeWidth, 14), Qt::AlignLeft | Qt::AlignTop, below);
}

void NodeItem::paintPorts(QPainter* p) const {
  QFont f = p->font();
  f.setPointSizeF(8);
  f.setBold(false);
  p->setFont(f);
  for (bool output : {false, true}) {
    const auto& ports = output ? decl_->outputs() : decl_->inputs();
    for (int i = 0; i < static_cast<int>(ports.size()); ++i) {
      const PortRef ref{output, i};
      const QPointF c = mapFromScene(portScenePos(ref));
      const bool lit =
          std::find(highlighted_.begin(), highlighted_.end(), ref) != highlighted_.end();
      const QColor colour = style::valueTypeColour(ports[i].type->name);
      p->setPen(QPen(lit ? style::portHighlight() : QColor(20, 20, 24), lit ? 3 : 1));
      p->setBrush(ports[i].optional ? colour.darker(140) : colour);
      const double r = lit ? style::kPortRadius + 2 : style::kPortRadius;
      p->drawEllipse(c, r, r);
      p->setPen(style::textColour());
      const QRectF label(output ? style::kNodeWidth / 2 : 10, c.y() - style::kRowHeight / 2,
                         style::kNodeWidth / 2 - 10, style::kRowHeight);
      QString text = QString::fromStdString(ports[i].name);
      if (!output && ports[i].multiple) text += " …";
      p->drawText(label, Qt::AlignVCenter | (output ? Qt::AlignRight : Qt::AlignLeft), text);
    }
  }
}

void NodeItem::paintBadge(QPainter* p) const {
  using S = NodeStatus::State;
  QColor colour;
  QString mark;
  switch (status_.state) {
    case S::Cooking:
      colour = style::cookingBlue(), mark = "…";
      break;
    case S::Failed:
      colour = style::errorRed(), mark = "!";
      break;
    case S::UpstreamFailed:
      colour = style::upstreamOrange(), mark = "↑";
      break;
    case S::Cooked:
    case S::Cached:
      colour = status_.warning ? style::warningYellow() : style::cookedGreen();
      mark = status_.warning ? "!" : "";
      break;
    case S::Cancelled:
      colour = QColor(120, 120, 120), mark = "×";
      break;
    case S::Idle:
      return;
  }
  const QPointF c(style::kNodeWidth - 13, style::kHeaderHeight / 2);
  p->setPen(QPen(QColor(20, 20, 24), 1));
  p->setBrush(colour);
  p->drawEllipse(c, style::kBadgeRadius, style::kBadgeRadius);
  if (status_.state == S::Cooking && status_.progress > 0) {
    p->setPen(QPen(Qt::white, 2));
    const QRectF arc(c.x() - 5, c.y() - 5, 10, 10);
    p->drawArc(arc, 90 * 16, -int(360 * 16 * std::clamp(status_.progress, 0.0, 1.0)));
    return;
  }
  if (mark.isEmpty()) return;
  QFont f = p->font();
  f.setBold(true);
  f.setPointSizeF(8.5);
  p->setFont(f);
  p->setPen(status_.state == S::Cooked || status_.state == S::Cached ? QColor(40, 30, 0)
                                                                     : Qt::white);
  p->drawText(QRectF(c.x() - 7, c.y() - 7, 14, 14), Qt::AlignCenter, mark);
}

}  // namespace tfd::ui
