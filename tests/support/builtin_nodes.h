#pragma once
// What the node tests share: the registry of every built-in node type, and a node report's
// messages as one text (for failure output and for searching).
#include <string>

#include "graph/evaluator.h"
#include "graph/node_registry.h"

namespace tfd::test {

/// Every built-in node type (nodes::registerAll), built once; lives as long as the program.
const graph::NodeRegistry& builtinNodes();

/// The report's messages, one per line.
std::string reportText(const graph::NodeReport& report);

}  // namespace tfd::test
