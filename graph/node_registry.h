#pragma once
// The node-type registry. Registration is explicit (nodes::registerAll calls one function per
// node file), never static-initialiser magic:
//
//   void registerPropagate(graph::NodeRegistry& r) { r.add("Propagate", 1, declare, cook); }
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/cook_context.h"
#include "graph/node_decl.h"

namespace tfd::graph {

using DeclareFn = std::function<void(NodeDecl&)>;
using CookFn = std::function<void(CookContext&)>;

class NodeType {
 public:
  NodeType(NodeDecl decl, CookFn cook) : decl_(std::move(decl)), cook_(std::move(cook)) {}
  const std::string& name() const { return decl_.typeName(); }
  int version() const { return decl_.typeVersion(); }
  const NodeDecl& decl() const { return decl_; }
  const CookFn& cook() const { return cook_; }

 private:
  NodeDecl decl_;
  CookFn cook_;
};

class NodeRegistry {
 public:
  NodeRegistry() = default;
  NodeRegistry(const NodeRegistry&) = delete;
  NodeRegistry& operator=(const NodeRegistry&) = delete;

  /// Declares and registers a node type. Throws std::logic_error on a duplicate type name, an
  /// invalid declaration (see NodeDecl::finalize) or a value-type display name already used by
  /// another C++ type. The returned reference stays valid for the registry's lifetime.
  const NodeType& add(std::string typeName, int typeVersion, const DeclareFn& declare, CookFn cook);

  const NodeType* find(std::string_view typeName) const;
  /// Throws GraphError "unknown node type \"X\"" (with a close match suggested, if any).
  const NodeType& get(std::string_view typeName) const;
  /// Every type, sorted by name.
  std::vector<const NodeType*> types() const;
  std::size_t size() const { return types_.size(); }
  /// The registered type name closest to `typeName` (edit distance <= 3), or "".
  std::string suggest(std::string_view typeName) const;

 private:
  std::map<std::string, std::unique_ptr<NodeType>, std::less<>> types_;
  std::map<std::string, const ValueType*, std::less<>> valueTypes_;
};

}  // namespace tfd::graph
