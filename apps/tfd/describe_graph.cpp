// `tfd info GRAPH.tfd.json`: what the file says (read leniently, so it also describes files
// this tfd cannot load), then whether it loads.
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/tfd/cli.h"
#include "apps/tfd/file_describers.h"
#include "graph/errors.h"
#include "graph/format_migrations.h"
#include "graph/graph_file.h"
#include "graph/json_text.h"

namespace tfd::cli {

int describeGraphFile(const std::filesystem::path& file, std::ostream& out,
                      const graph::NodeRegistry& registry) {
  graph::Json doc;
  try {
    doc = graph::parseJsonText(graph::readTextFile(file), file.string());
  } catch (const graph::GraphError& e) {
    printError(e.what());
    return kUsage;
  }
  if (!doc.is_object() || doc.value("format", graph::Json()) != graph::kGraphFormatName) {
    printError(file.string() + ": not a tfd graph (no \"format\": \"tfd-graph\")");
    return kUsage;
  }
  out << "file: " << file.string() << "\n";
  const graph::Json version = doc.value("formatVersion", graph::Json());
  out << "format: tfd-graph, version "
      << (version.is_null() ? "(missing)" : graph::compactJson(version));
  if (version.is_number_integer() && version.get<long long>() < graph::kGraphFormatVersion)
    out << " (current: " << graph::kGraphFormatVersion << "; 'tfd upgrade' rewrites it)";
  out << "\n";
  if (doc.contains("generator")) {
    const graph::Json& g = doc["generator"];
    out << "generator: " << (g.is_string() ? g.get<std::string>() : graph::compactJson(g)) << "\n";
  }
  if (doc.contains("nodes") && doc["nodes"].is_object()) {
    out << "nodes: " << doc["nodes"].size() << "\n";
    for (const auto& [name, node] : doc["nodes"].items()) {
      out << "  " << name;
      if (node.is_object() && node.contains("type")) {
        const graph::Json& type = node["type"];
        out << "  " << (type.is_string() ? type.get<std::string>() : graph::compactJson(type));
        if (node.contains("typeVersion")) out << " v" << graph::compactJson(node["typeVersion"]);
      }
      out << "\n";
    }
  }
  if (doc.contains("links") && doc["links"].is_array())
    out << "links: " << doc["links"].size() << "\n";
  try {
    graph::graphFromJson(doc, registry, file.string());
    out << "status: loads\n";
    return kOk;
  } catch (const graph::GraphError& e) {
    out << "status: does not load\n";
    printError(e.what());
    return kUsage;
  }
}

}  // namespace tfd::cli
