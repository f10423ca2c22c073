#pragma once
// What a node reports: three severities (Houdini/Gaffer convention) and a kind that says where
// the message comes from, so a CLI or an editor can word or badge it without matching text.
//
//   kind             severity        port            sourceNode
//   Reported         any             -               -           c.info() / c.warning()
//   CookFailed       Error           -               -           the node's cook threw
//   OutputNotSet     Error           the output      -           cook returned without it
//   MissingInput     Error           the input       -           required input not linked
//   UpstreamFailed   Error           the input       failed node an input's node failed
//
// `text` is always filled (the words `tfd cook` prints), e.g. for UpstreamFailed
// "input 'field' failed upstream in node \"propagate1\"".
#include <string>
#include <string_view>

namespace tfd::graph {

enum class Severity { Info, Warning, Error };

enum class MessageKind { Reported, CookFailed, OutputNotSet, MissingInput, UpstreamFailed };

struct NodeMessage {
  Severity severity = Severity::Info;
  std::string text{};
  MessageKind kind = MessageKind::Reported;
  std::string port{};        ///< MissingInput, UpstreamFailed: the input; OutputNotSet: the output
  std::string sourceNode{};  ///< UpstreamFailed: the node whose own failure reached this input
  bool operator==(const NodeMessage&) const = default;
};

inline std::string_view severityName(Severity s) {
  return s == Severity::Info ? "info" : s == Severity::Warning ? "warning" : "error";
}

std::string_view messageKindName(MessageKind kind);

/// "input 'PORT' failed upstream in node \"NODE\"", as an UpstreamFailed error.
NodeMessage upstreamFailedMessage(std::string port, std::string sourceNode);
/// "required input 'PORT' is not connected", as a MissingInput error.
NodeMessage missingInputMessage(std::string port);

}  // namespace tfd::graph
