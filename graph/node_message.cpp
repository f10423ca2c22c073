#include "graph/node_message.h"

namespace tfd::graph {

std::string_view messageKindName(MessageKind kind) {
  switch (kind) {
    case MessageKind::Reported:
      return "reported";
    case MessageKind::CookFailed:
      return "cook failed";
    case MessageKind::OutputNotSet:
      return "output not set";
    case MessageKind::MissingInput:
      return "missing input";
    case MessageKind::UpstreamFailed:
      return "upstream failed";
  }
  return "?";
}

NodeMessage upstreamFailedMessage(std::string port, std::string sourceNode) {
  NodeMessage m;
  m.severity = Severity::Error;
  m.kind = MessageKind::UpstreamFailed;
  m.text = "input '" + port + "' failed upstream in node \"" + sourceNode + "\"";
  m.port = std::move(port);
  m.sourceNode = std::move(sourceNode);
  return m;
}

NodeMessage missingInputMessage(std::string port) {
  NodeMessage m;
  m.severity = Severity::Error;
  m.kind = MessageKind::MissingInput;
  m.text = "required input '" + port + "' is not connected";
  m.port = std::move(port);
  return m;
}

}  // namespace tfd::graph
