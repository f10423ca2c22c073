#pragma once
// The node reference, generated from the registry's declarations: plain text (`tfd nodes`,
// `tfd nodes TYPE`), Markdown (`tfd nodes --markdown`, committed as docs/nodes.md) and JSON
// (`tfd nodes --json`, for editors and scripts). Deterministic: types sorted by name, ports and
// parameters in declaration order.
#include <string>

#include "graph/json_fwd.h"
#include "graph/node_registry.h"

namespace tfd::graph {

/// One line per type: name, version and the first sentence of its doc.
std::string nodeTypesText(const NodeRegistry& registry);
/// Every port and parameter of one type.
std::string nodeTypeText(const NodeType& type);
std::string nodeTypesMarkdown(const NodeRegistry& registry);
/// {"format": "tfd-node-types", "generator": ..., "nodeTypes": [...]}
Json nodeTypesJson(const NodeRegistry& registry);
Json nodeTypeJson(const NodeType& type);

}  // namespace tfd::graph
