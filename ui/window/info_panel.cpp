#include "ui/window/info_panel.h"

namespace tfd::ui {

namespace {

QString colourOf(graph::Severity s) {
  switch (s) {
    case graph::Severity::Error:
      return "#e05050";
    case graph::Severity::Warning:
      return "#d0a020";
    default:
      return "palette(text)";
  }
}

QString messagesHtml(const NodeStatus& s) {
  QString html;
  for (const graph::NodeMessage& m : s.messages)
    html += QString("<div style='color:%1'>%2: %3</div>")
                .arg(colourOf(m.severity),
                     QString::fromStdString(std::string(graph::severityName(m.severity))),
                     QString::fromStdString(m.text).toHtmlEscaped());
  return html;
}

QString stateHtml(const std::string& node, const NodeStatus& s) {
  QString text = QString("<b>%1</b>: %2")
                     .arg(QString::fromStdString(node).toHtmlEscaped(), stateLabel(s.state));
  if (s.state == NodeStatus::State::UpstreamFailed && !s.failedNode.empty())
    text += " (" + QString::fromStdString(s.failedNode).toHtmlEscaped() + ")";
  if (s.state == NodeStatus::State::Cooked) text += QString(" in %1 s").arg(s.seconds, 0, 'f', 3);
  return text;
}

}  // namespace

InfoPanel::InfoPanel(CookController& cook, QWidget* parent) : QTextBrowser(parent), cook_(cook) {
  setOpenLinks(false);
  connect(&cook_, &CookController::cookFinished, this, &InfoPanel::refresh);
  connect(&cook_, &CookController::statusChanged, this, [this](const QString& node) {
    if (node.toStdString() == node_) refresh();
  });
  refresh();
}

void InfoPanel::setNode(const std::string& node) {
  node_ = node;
  refresh();
}

void InfoPanel::refresh() {
  QString html;
  const NodeStatusMap& statuses = cook_.statuses();
  if (!node_.empty()) {
    auto it = statuses.find(node_);
    if (it == statuses.end()) {
      html += "<b>" + QString::fromStdString(node_).toHtmlEscaped() + "</b>: not cooked yet";
    } else {
      html += stateHtml(node_, it->second) + messagesHtml(it->second);
    }
  }
  QString problems;
  for (const auto& [node, s] : statuses)
    if (node != node_ && (s.state == NodeStatus::State::Failed || s.warning))
      problems += "<p>" + stateHtml(node, s) + messagesHtml(s) + "</p>";
  if (!problems.isEmpty()) html += "<hr><b>Problems elsewhere</b>" + problems;
  if (html.isEmpty()) html = "<span style='color:gray'>Select a node to see its messages.</span>";
  setHtml(html);
}

}  // namespace tfd::ui
