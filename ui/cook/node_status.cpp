#include "ui/cook/node_status.h"

#include <cstdio>

namespace tfd::ui {

std::string NodeStatus::headline() const {
  for (graph::Severity s : {graph::Severity::Error, graph::Severity::Warning})
    for (const graph::NodeMessage& m : messages)
      if (m.severity == s) return m.text;
  return {};
}

std::string NodeStatus::details() const {
  std::string out;
  for (const graph::NodeMessage& m : messages) {
    if (!out.empty()) out += '\n';
    out += std::string(graph::severityName(m.severity)) + ": " + m.text;
  }
  return out;
}

NodeStatus statusFromReport(const graph::NodeReport& report) {
  NodeStatus s;
  using graph::NodeState;
  switch (report.state) {
    case NodeState::NotRequested:
      s.state = NodeStatus::State::Idle;
      break;
    case NodeState::Cooked:
      s.state = NodeStatus::State::Cooked;
      break;
    case NodeState::Cached:
      s.state = NodeStatus::State::Cached;
      break;
    case NodeState::Failed:
      s.state = NodeStatus::State::Failed;
      break;
    case NodeState::UpstreamFailed:
      s.state = NodeStatus::State::UpstreamFailed;
      break;
    case NodeState::Cancelled:
      s.state = NodeStatus::State::Cancelled;
      break;
  }
  s.warning = report.hasWarnings();
  s.seconds = report.seconds;
  s.failedNode = report.failedNode;
  s.messages = report.messages;
  return s;
}

const char* stateLabel(NodeStatus::State state) {
  switch (state) {
    case NodeStatus::State::Idle:
      return "not cooked";
    case NodeStatus::State::Cooking:
      return "cooking";
    case NodeStatus::State::Cooked:
      return "cooked";
    case NodeStatus::State::Cached:
      return "cached";
    case NodeStatus::State::Failed:
      return "error";
    case NodeStatus::State::UpstreamFailed:
      return "downstream of an error";
    case NodeStatus::State::Cancelled:
      return "cancelled";
  }
  return "";
}

}  // namespace tfd::ui
