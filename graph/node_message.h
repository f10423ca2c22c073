#pragma once
// The three severities of what a node reports (Houdini/Gaffer convention).
#include <string>
#include <string_view>

namespace tfd::graph {

enum class Severity { Info, Warning, Error };

struct NodeMessage {
  Severity severity = Severity::Info;
  std::string text;
  bool operator==(const NodeMessage&) const = default;
};

inline std::string_view severityName(Severity s) {
  return s == Severity::Info ? "info" : s == Severity::Warning ? "warning" : "error";
}

}  // namespace tfd::graph
