#pragma once
namespace tfd::graph {
class NodeRegistry;
}
namespace tfd::nodes {
/// Registers every built-in node type. Explicit (not static-initialiser magic) so that linking
/// the static library never drops a node type.
void registerAll(graph::NodeRegistry& registry);
}  // namespace tfd::nodes
