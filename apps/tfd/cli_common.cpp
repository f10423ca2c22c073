#include <iostream>

#include "apps/tfd/cli.h"
#include "graph/errors.h"
#include "graph/graph_file.h"

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

}  // namespace tfd::cli
