#include "nodes/register_all.h"
namespace tfd::nodes {
void registerAll(graph::NodeRegistry&) {}
}  // namespace tfd::nodes
