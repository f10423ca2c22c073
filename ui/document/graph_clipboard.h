#pragma once
// Copy and paste of nodes as the file format's JSON text (paste into a text editor and back).
#include <QPointF>

#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"

namespace tfd::ui {

/// A graph holding the named nodes of `graph` (document order, same names, parameters and ui
/// data) and the links between them. Throws GraphError for an unknown name.
graph::Graph extractNodes(const graph::Graph& graph, const std::vector<std::string>& names);

/// Adds every node of `pasted` to `target` with its links: names already taken get the next
/// free "<name without trailing digits><n>", positions move by `offset`, display flags are
/// dropped. Returns the new names in `pasted`'s order. Throws GraphError (nothing is left half
/// done only if the caller works on a copy, as GraphDocument does).
std::vector<std::string> mergeNodes(graph::Graph& target, const graph::Graph& pasted,
                                    QPointF offset);

/// Parses clipboard text: a graph file's text (LoadError with source "clipboard" otherwise).
graph::Graph parseClipboard(std::string_view text, const graph::NodeRegistry& registry);

}  // namespace tfd::ui
