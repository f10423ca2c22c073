#pragma once
// What the editor shows about a node's last cook: the badges of the canvas (cooking, error,
// warning, downstream of an error, cook time) and the info panel's messages.
#include <map>
#include <string>
#include <vector>

#include "graph/evaluator.h"

namespace tfd::ui {

struct NodeStatus {
  enum class State { Idle, Cooking, Cooked, Cached, Failed, UpstreamFailed, Cancelled };
  State state = State::Idle;
  bool warning = false;    ///< cooked with at least one warning
  double seconds = 0;      ///< wall time of the cook that produced the result
  double progress = 0;     ///< while cooking, in [0, 1]
  std::string failedNode;  ///< UpstreamFailed: the node whose failure reached here
  std::vector<graph::NodeMessage> messages;

  bool hasError() const { return state == State::Failed || state == State::UpstreamFailed; }
  /// The first error (or warning) text; "" when none.
  std::string headline() const;
  /// Every message, one per line, prefixed by its severity (for tooltips and the info panel).
  std::string details() const;
};

NodeStatus statusFromReport(const graph::NodeReport& report);
const char* stateLabel(NodeStatus::State state);

using NodeStatusMap = std::map<std::string, NodeStatus, std::less<>>;

}  // namespace tfd::ui
