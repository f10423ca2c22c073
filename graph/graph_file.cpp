#include "graph/graph_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graph/atomic_write.h"
#include "graph/errors.h"
#include "graph/format_migrations.h"
#include "graph/json_text.h"
#include "graph/version.h"

namespace tfd::graph {

namespace {

/// Where loading puts its problems: null throws the first one (loadGraphFile), else each is
/// recorded and loading goes on (loadGraphFileCollecting).
using Problems = std::vector<LoadProblem>;

void record(Problems* problems, const LoadError& e, std::string node, std::string parameter = {}) {
  if (!problems) throw e;
  problems->push_back({e.pointer(), std::move(node), std::move(parameter), e.message()});
}

std::string keyList(std::initializer_list<const char*> keys) {
  std::string out;
  for (const char* k : keys) out += (out.empty() ? "" : ", ") + std::string(k);
  return out;
}

void checkKeys(const Json& object, std::initializer_list<const char*> allowed,
               const std::string& source, const std::string& pointer) {
  for (const auto& [key, value] : object.items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || key == a;
    if (!ok)
      throw LoadError(source, pointerJoin(pointer, key),
                      "unknown key \"" + key + "\" (expected " + keyList(allowed) + ")");
  }
}

template <class C>
std::string names(const C& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item.name;
  return out.empty() ? "none" : out;
}

void loadNode(Graph& graph, const std::string& name, const Json& j, const std::string& source,
              Problems* problems) {
  const std::string where = pointerJoin("/nodes", name);
  if (!Graph::isValidNodeName(name))
    throw LoadError(source, where,
                    "invalid node name \"" + name +
                        "\" (use 1-64 letters, digits, '_' or '-', starting with a letter or '_')");
  if (!j.is_object())
    throw LoadError(source, where, "expected a node object, found " + describeJson(j));
  checkKeys(j, {"type", "typeVersion", "params", "ui"}, source, where);
  if (!j.contains("type")) throw LoadError(source, where, "missing \"type\"");
  if (!j["type"].is_string())
    throw LoadError(source, where + "/type", "expected a string, found " + describeJson(j["type"]));
  const std::string typeName = j["type"].get<std::string>();
  const NodeType* type = graph.registry().find(typeName);
  if (!type) {
    std::string message = "unknown node type \"" + typeName + "\"";
    if (std::string s = graph.registry().suggest(typeName); !s.empty())
      message += " (did you mean \"" + s + "\"?)";
    throw LoadError(source, where + "/type", message);
  }
  if (!j.contains("typeVersion")) throw LoadError(source, where, "missing \"typeVersion\"");
  const Json& tv = j["typeVersion"];
  if (!tv.is_number_integer() || tv.get<long long>() < 1)
    throw LoadError(source, where + "/typeVersion",
                    "expected an integer >= 1, found " + describeJson(tv));
  const long long typeVersion = tv.get<long long>();
  if (typeVersion > type->version())
    throw LoadError(source, where + "/typeVersion",
                    "typeVersion " + std::to_string(typeVersion) + " of node type " + typeName +
                        " is newer than this tfd (" + toolVersion() + ") supports (" +
                        std::to_string(type->version()) + "); use a newer tfd");
  Json params = j.contains("params") ? j["params"] : Json::object();
  if (!params.is_object())
    throw LoadError(source, where + "/params", "expected an object, found " + describeJson(params));
  for (long long v = typeVersion; v < type->version(); ++v) {
    const ParamMigration* upgrade = type->decl().migrationFrom(static_cast<int>(v));
    if (!upgrade)
      throw LoadError(source, where + "/typeVersion",
                      "node type " + typeName + " cannot be upgraded from typeVersion " +
                          std::to_string(v) + " (no migration to " + std::to_string(v + 1) + ")");
    try {
      (*upgrade)(params);
    } catch (const std::exception& e) {
      throw LoadError(source, where + "/params",
                      "upgrading " + typeName + " from typeVersion " + std::to_string(v) + " to " +
                          std::to_string(v + 1) + ": " + e.what());
    }
    if (!params.is_object())
      throw LoadError(source, where + "/params", "migration of " + typeName + " broke params");
  }
  try {
    graph.addNode(typeName, name);
  } catch (const GraphError& e) {
    throw LoadError(source, where, e.what());
  }
  const NodeDecl& decl = type->decl();
  for (const auto& [key, value] : params.items()) {
    const std::string at = pointerJoin(where + "/params", key);
    const ParamDecl* p = decl.findParam(key);
    if (!p) {
      record(problems,
             LoadError(source, at,
                       "unknown parameter \"" + key + "\" of node type " + typeName +
                           " (parameters: " + names(decl.params()) + ")"),
             name, key);
      continue;
    }
    try {
      graph.setParam(name, key, paramFromJson(*p, value));
    } catch (const GraphError& e) {
      record(problems, LoadError(source, at, e.what()), name, key);
    }
  }
  if (j.contains("ui")) {
    if (!j["ui"].is_object())
      throw LoadError(source, where + "/ui", "expected an object, found " + describeJson(j["ui"]));
    graph.setUi(name, j["ui"]);
  }
}

void loadLink(Graph& graph, const Json& j, std::size_t index, const std::string& source,
              const std::vector<std::string>& skippedNodes) {
  const std::string where = pointerJoin("/links", index);
  if (!j.is_object())
    throw LoadError(
        source, where,
        "expected {\"from\": \"node.port\", \"to\": \"node.port\"}, found " + describeJson(j));
  checkKeys(j, {"from", "to"}, source, where);
  Endpoint ends[2];
  const char* keys[2] = {"from", "to"};
  for (int k = 0; k < 2; ++k) {
    const std::string at = where + "/" + keys[k];
    if (!j.contains(keys[k]))
      throw LoadError(source, where, std::string("missing \"") + keys[k] + "\"");
    const Json& e = j[keys[k]];
    if (!e.is_string())
      throw LoadError(source, at, "expected \"node.port\", found " + describeJson(e));
    try {
      ends[k] = Endpoint::parse(e.get<std::string>());
    } catch (const GraphError& err) {
      throw LoadError(source, at, err.what());
    }
    for (const std::string& skipped : skippedNodes)
      if (ends[k].node == skipped) return;  // its node did not load: already reported
    if (auto why = graph.checkEndpoint(ends[k], k == 0)) throw LoadError(source, at, *why);
  }
  try {
    graph.connect(ends[0], ends[1]);
  } catch (const GraphError& e) {
    throw LoadError(source, where, e.what());
  }
}

/// The node a link's problem concerns: its "to" node when that can be read.
std::string linkNode(const Json& j) {
  if (!j.is_object() || !j.contains("to") || !j["to"].is_string()) return {};
  const std::string to = j["to"].get<std::string>();
  return to.substr(0, to.find('.'));
}

Graph graphFromJsonImpl(const Json& input, const NodeRegistry& registry, const std::string& source,
                        Problems* problems) {
  int originalVersion = 0;
  Json doc = migrateGraphDocument(input, source, &originalVersion);
  checkKeys(doc, {"format", "formatVersion", "generator", "nodes", "links"}, source, "");
  if (doc.contains("generator") && !doc["generator"].is_string())
    throw LoadError(source, "/generator",
                    "expected a string, found " + describeJson(doc["generator"]));
  Graph graph(registry);
  graph.setLoadedFormatVersion(originalVersion);
  if (!doc.contains("nodes")) throw LoadError(source, "/nodes", "missing (use {} for none)");
  if (!doc["nodes"].is_object())
    throw LoadError(source, "/nodes",
                    "expected an object of nodes by name, found " + describeJson(doc["nodes"]));
  std::vector<std::string> skipped;
  for (const auto& [name, node] : doc["nodes"].items()) {
    try {
      loadNode(graph, name, node, source, problems);
    } catch (const LoadError& e) {
      record(problems, e, name);
      if (graph.findNode(name)) graph.removeNode(name);
      skipped.push_back(name);
    }
  }
  if (!doc.contains("links")) throw LoadError(source, "/links", "missing (use [] for none)");
  if (!doc["links"].is_array())
    throw LoadError(source, "/links", "expected an array, found " + describeJson(doc["links"]));
  for (std::size_t i = 0; i < doc["links"].size(); ++i) {
    try {
      loadLink(graph, doc["links"][i], i, source, skipped);
    } catch (const LoadError& e) {
      record(problems, e, linkNode(doc["links"][i]));
    }
  }
  return graph;
}

}  // namespace

Graph graphFromJson(const Json& input, const NodeRegistry& registry, const std::string& source) {
  return graphFromJsonImpl(input, registry, source, nullptr);
}

Graph parseGraph(std::string_view text, const NodeRegistry& registry, const std::string& source) {
  const Json json = parseJsonText(text, source);
  try {
    return graphFromJson(json, registry, source);
  } catch (const GraphError&) {
    throw;
  } catch (const std::exception& e) {  // a library exception is a load error too, never abort
    throw LoadError(source, "", printableText(e.what()));
  }
}

std::string readTextFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw LoadError(path.string(), "", "cannot read: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LoadError(path.string(), "", std::string("cannot read: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw LoadError(path.string(), "", "cannot read: I/O error");
  return buffer.str();
}

std::optional<Graph> loadGraphFileCollecting(const std::filesystem::path& path,
                                             const NodeRegistry& registry,
                                             std::vector<LoadProblem>& problems) {
  try {
    const Json json = parseJsonText(readTextFile(path), path.string());
    Graph graph = graphFromJsonImpl(json, registry, path.string(), &problems);
    graph.setSourcePath(path);
    return graph;
  } catch (const LoadError& e) {  // the document itself
    problems.push_back({e.pointer(), {}, {}, e.message()});
  } catch (const std::exception& e) {
    problems.push_back({{}, {}, {}, printableText(e.what())});
  }
  return std::nullopt;
}

Graph loadGraphFile(const std::filesystem::path& path, const NodeRegistry& registry) {
  Graph graph = parseGraph(readTextFile(path), registry, path.string());
  graph.setSourcePath(path);
  return graph;
}

Json graphToJson(const Graph& graph) {
  Json doc = Json::object();
  doc["format"] = kGraphFormatName;
  doc["formatVersion"] = kGraphFormatVersion;
  doc["generator"] = std::string("tfd ") + toolVersion();
  Json nodes = Json::object();
  for (const Node& n : graph.nodes()) {
    Json j = Json::object();
    j["type"] = n.type().name();
    j["typeVersion"] = n.type().version();
    Json params = Json::object();
    const auto& decls = n.decl().params();
    for (std::size_t i = 0; i < decls.size(); ++i)
      if (n.isSet(i)) params[decls[i].name] = paramToJson(n.paramAt(i));
    j["params"] = std::move(params);
    j["ui"] = n.ui();
    nodes[n.name()] = std::move(j);
  }
  doc["nodes"] = std::move(nodes);
  Json links = Json::array();
  for (const Link& l : graph.links()) {
    Json j = Json::object();
    j["from"] = l.from.str();
    j["to"] = l.to.str();
    links.push_back(std::move(j));
  }
  doc["links"] = std::move(links);
  return doc;
}

std::string graphToText(const Graph& graph) { return formatJson(graphToJson(graph)); }

void saveGraphFile(const Graph& graph, const std::filesystem::path& path) {
  writeTextFileAtomically(path, graphToText(graph));
}

}  // namespace tfd::graph
