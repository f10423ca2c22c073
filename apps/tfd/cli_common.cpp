#include <iostream>

#include "apps/tfd/cli.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "graph/errors.h"
#include "graph/graph_file.h"
#include "graph/overrides.h"

namespace tfd::cli {

void printError(const std::string& message) {
  // Messages quote names and text from input files; whatever a layer let through, no raw
  // control byte reaches the terminal (line breaks and tabs of multi-line messages stay).
  std::string shown;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      shown += {'\\', 'x', hex[u >> 4], hex[u & 15]};
    } else {
      shown += c;
    }
  }
  std::cerr << "tfd: " << shown << "\n";
}

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

void addMaxMemoryOption(CLI::App& cmd) {
  cmd.add_option_function<std::string>(
         "--max-memory",
         [](const std::string& text) {
           try {
             core::setMemoryBudget(core::parseByteSize(text));
           } catch (const core::Error& e) {
             throw CLI::ValidationError("--max-memory", e.what());
           }
         },
         "Memory budget, e.g. 4G or 512M (default: the memory available now). What a file or "
         "a parameter announces (grid sizes, tet and triangle counts) is checked against it "
         "before anything is allocated.")
      ->type_name("SIZE");
}

}  // namespace tfd::cli
