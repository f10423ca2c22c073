#pragma once
// Resolution of file parameters. Relative input files resolve against the graph file's folder;
// relative output files against the output directory (--out), which defaults to that folder.
// Resolved paths are absolute and lexically normal.
#include <filesystem>
#include <string>
#include <vector>

#include "graph/graph.h"

namespace tfd::graph {

struct PathContext {
  std::filesystem::path baseDir;  ///< folder of the graph file (absolute)
  std::filesystem::path outDir;   ///< where relative outputs go (absolute)
};

/// baseDir: `baseDir` if given, else the graph's source folder, else the current directory.
/// outDir: `outDir` if given (made absolute), else baseDir.
PathContext makePathContext(const Graph& graph, const std::filesystem::path& outDir = {},
                            const std::filesystem::path& baseDir = {});

/// The resolved path of a file parameter's value; other values unchanged. Empty stays empty.
std::string resolvePath(const ParamDecl& decl, const std::string& value, const PathContext& ctx);

/// For an output-file parameter whose declaration lists extensions (`outputFile("*.vtu")`):
/// empty when `value` ends in one of them (case-insensitively) or is empty, otherwise why not,
/// e.g. "'x.vdb' does not end in .vtu, the kind of file this node writes". Writers choose
/// their format by node type, so a mismatched name would hide what the file holds.
std::string outputExtensionProblem(const ParamDecl& decl, const std::string& value);

/// The node's effective parameter values in declaration order, file paths resolved.
std::vector<ParamValue> resolvedParams(const Node& node, const PathContext& ctx);

}  // namespace tfd::graph
