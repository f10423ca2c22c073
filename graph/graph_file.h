#pragma once
// Reading and writing graph files (`*.tfd.json`, format in docs/file-format.md).
//
// Loading migrates old format versions (format_migrations.h) and old node typeVersions (the
// node type's NodeDecl::migration hooks), then builds the Graph through its validating API.
// Every problem is a LoadError naming the file, the JSON pointer of the place
// (e.g. /nodes/propagate1/params/radius or /links/2/to) and what was expected and found:
// unknown keys, node types or parameters, wrong parameter types, ranges or choices, links to
// unknown nodes or ports, type-mismatched links, several links into a single input, cycles.
//
// Saving writes the canonical form: keys in a fixed order, nodes in graph order, only
// parameters that differ from their default, in declaration order; so save -> load -> save is
// byte-identical.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/json_fwd.h"

namespace tfd::graph {

/// `source` names the document in messages (usually the file path).
Graph graphFromJson(const Json& doc, const NodeRegistry& registry, const std::string& source);
Graph parseGraph(std::string_view text, const NodeRegistry& registry, const std::string& source);
/// Reads a file; the graph's sourcePath() is set to `path`. A missing or unreadable file is a
/// LoadError too.
Graph loadGraphFile(const std::filesystem::path& path, const NodeRegistry& registry);

/// One problem found by loadGraphFileCollecting.
struct LoadProblem {
  std::string pointer;    ///< JSON pointer of the place in the file ("" for the whole file)
  std::string node;       ///< the node concerned (a link's: its "to" node); empty when none
  std::string parameter;  ///< the parameter concerned; empty when none
  std::string message;
};
/// Like loadGraphFile, but goes on after a problem and records each one (file order): a node
/// that cannot be made (unknown type or key, bad typeVersion) is left out with its links; a
/// bad or unknown parameter keeps its default; a bad link (unknown node or port, type
/// mismatch, second link into a single input, cycle) is dropped. Nothing is returned only when
/// the document itself cannot be read (unreadable, not JSON, not a graph, newer format); then
/// `problems` holds that one.
std::optional<Graph> loadGraphFileCollecting(const std::filesystem::path& path,
                                             const NodeRegistry& registry,
                                             std::vector<LoadProblem>& problems);

/// The canonical JSON of the current format version.
Json graphToJson(const Graph& graph);
/// formatJson(graphToJson(graph)).
std::string graphToText(const Graph& graph);
/// Atomic write (temporary file + rename). Throws GraphError on failure.
void saveGraphFile(const Graph& graph, const std::filesystem::path& path);

/// Reads a whole file into a string; throws LoadError(path, "", "cannot read: <reason>").
std::string readTextFile(const std::filesystem::path& path);

}  // namespace tfd::graph
