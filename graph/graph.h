#pragma once
// The graph document: named nodes with their parameter values and editor data, and links
// between named ports. Every edit is validated against the node registry, so a Graph is always
// well formed: known node types, in-range parameters, links between existing ports of the same
// value type, at most one link into a single input, no cycles. (Required inputs may still be
// unconnected while a graph is being edited; see validation.h.)
//
// A Graph is a value: copy it to cook a snapshot in the background while the original is
// edited. Not thread-safe for concurrent edits.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "graph/json_fwd.h"
#include "graph/node_registry.h"

namespace tfd::graph {

/// "node.port"
struct Endpoint {
  std::string node, port;
  std::string str() const { return node + "." + port; }
  /// Splits at the first '.'; throws GraphError "expected \"node.port\", found ..." otherwise.
  static Endpoint parse(std::string_view text);
  bool operator==(const Endpoint&) const = default;
};

struct Link {
  Endpoint from;  ///< an output
  Endpoint to;    ///< an input
  bool operator==(const Link&) const = default;
};

class Node {
 public:
  const std::string& name() const { return name_; }
  const NodeType& type() const { return *type_; }
  const NodeDecl& decl() const { return type_->decl(); }
  /// Effective value (the stored override or the declared default).
  const ParamValue& param(std::string_view name) const;
  const ParamValue& paramAt(std::size_t index) const;
  /// True when the value differs from the default (only these are saved).
  bool isSet(std::size_t index) const { return overrides_[index].has_value(); }
  /// Editor data (position, collapsed...): an object, kept verbatim, ignored by cooking.
  const Json& ui() const { return ui_; }

 private:
  friend class Graph;
  std::string name_;
  const NodeType* type_ = nullptr;
  std::vector<std::optional<ParamValue>> overrides_;
  Json ui_ = Json::object();
};

class Graph {
 public:
  explicit Graph(const NodeRegistry& registry) : registry_(&registry) {}

  const NodeRegistry& registry() const { return *registry_; }

  // ---- nodes (kept in insertion / file order)
  /// Adds a node of a registered type. An empty name picks "<type in lower case><n>". Throws
  /// GraphError for an unknown type, an invalid name or a name in use.
  const Node& addNode(std::string_view typeName, std::string_view name = {});
  /// Removes the node and every link to or from it.
  void removeNode(std::string_view name);
  /// Renames a node and updates its links.
  void renameNode(std::string_view from, std::string_view to);
  const Node* findNode(std::string_view name) const;
  /// Throws GraphError "unknown node \"x\"".
  const Node& node(std::string_view name) const;
  std::size_t nodeCount() const { return nodes_.size(); }
  /// Index of a node in nodes(), or -1.
  int nodeIndex(std::string_view name) const;
  const std::vector<Node>& nodes() const { return nodes_; }
  /// "<base><n>" with the smallest n >= 1 not in use.
  std::string uniqueName(std::string_view base) const;
  /// Names are 1-64 characters [A-Za-z0-9_-], starting with a letter or '_'.
  static bool isValidNodeName(std::string_view name);

  // ---- parameters
  /// Checks and stores a value (int -> double converted). A value equal to the default clears
  /// the override. Throws GraphError naming node and parameter: `parameter "radius" of node
  /// "p1" (Propagate): expected a number >= 0, found -1`.
  void setParam(std::string_view node, std::string_view param, ParamValue value);
  void resetParam(std::string_view node, std::string_view param);
  const ParamValue& param(std::string_view node, std::string_view param) const;

  void setUi(std::string_view node, Json ui);

  // ---- links
  /// Appends a link (links into a `multiple` input keep their order). Throws GraphError for an
  /// unknown node/port, an output used as input or vice versa, differing value types, a second
  /// link into a single input, a duplicate link or a cycle (the message names the cycle).
  void connect(const Endpoint& from, const Endpoint& to);
  /// Removes the link; returns false when there was none.
  bool disconnect(const Endpoint& from, const Endpoint& to);
  const std::vector<Link>& links() const { return links_; }
  /// Links into node.port, in order.
  std::vector<Link> linksInto(std::string_view node, std::string_view port) const;
  /// Reason why `e` is not an existing output (output == true) or input, or nothing.
  std::optional<std::string> checkEndpoint(const Endpoint& e, bool output) const;

  // ---- provenance
  /// The file the graph was loaded from or saved to (relative paths resolve against its folder).
  const std::filesystem::path& sourcePath() const { return sourcePath_; }
  void setSourcePath(std::filesystem::path p) { sourcePath_ = std::move(p); }
  /// formatVersion of the file as read (before migrations); 0 when not loaded from a file.
  int loadedFormatVersion() const { return loadedFormatVersion_; }
  void setLoadedFormatVersion(int v) { loadedFormatVersion_ = v; }

  /// Incremented by every successful edit (an editor's cheap "changed?" check).
  std::uint64_t revision() const { return revision_; }

 private:
  Node& mutableNode(std::string_view name);
  void rebuildIndex();
  /// A path of node names from `from` to `to` following links, empty when there is none.
  std::vector<std::string> pathBetween(const std::string& from, const std::string& to) const;

  const NodeRegistry* registry_;
  std::vector<Node> nodes_;
  std::map<std::string, int, std::less<>> index_;
  std::vector<Link> links_;
  std::filesystem::path sourcePath_;
  int loadedFormatVersion_ = 0;
  std::uint64_t revision_ = 0;
};

}  // namespace tfd::graph
