#include <iostream>

#include "apps/tfd/cli.h"
#include "graph/errors.h"
#include "graph/graph_file.h"
#include "graph/overrides.h"

namespace tfd::cli {

void printError(const std::string& message) { std::cerr << "tfd: " << message << "\n"; }

std::optional<graph::Graph> loadGraphOrReport(const std::filesystem::path& path,
                                              const graph::NodeRegistry& registry) {
  try {
    return graph::loadGraphFile(path, registry);
  } catch (const graph::GraphError& e) {
    printError(e.what());
  } catch (const std::exception& e) {  // any library exception is still a load error
    printError(path.string() + ": " + e.what());
  }
  return std::nullopt;
}

std::optional<graph::Graph> loadGraphWithOverrides(const std::filesystem::path& path,
                                                   const graph::NodeRegistry& registry,
                                                   const std::vector<std::string>& sets) {
  std::optional<graph::Graph> graph = loadGraphOrReport(path, registry);
  if (!graph) return std::nullopt;
  for (const std::string& text : sets) {
    try {
      graph::applyOverride(*graph, graph::parseOverride(text));
    } catch (const graph::GraphError& e) {
      printError(e.what());
      return std::nullopt;
    }
  }
  return graph;
}

}  // namespace tfd::cli
