#include "tests/support/builtin_nodes.h"

#include "nodes/register_all.h"

namespace tfd::test {

const graph::NodeRegistry& builtinNodes() {
  static const graph::NodeRegistry& registry = *[] {
    auto* out = new graph::NodeRegistry;  // never destroyed: tests may use it at exit
    nodes::registerAll(*out);
    return out;
  }();
  return registry;
}

std::string reportText(const graph::NodeReport& report) {
  std::string text;
  for (const auto& m : report.messages) text += m.text + "\n";
  return text;
}

}  // namespace tfd::test
