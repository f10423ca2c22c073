#include "graph/node_registry.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace tfd::graph {

namespace {
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                  std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}
}  // namespace

const NodeType& NodeRegistry::add(std::string typeName, int typeVersion, const DeclareFn& declare,
                                  CookFn cook) {
  if (types_.count(typeName))
    throw std::logic_error("node type \"" + typeName + "\" is registered twice");
  if (!cook) throw std::logic_error("node type \"" + typeName + "\" has no cook function");
  NodeDecl decl(typeName, typeVersion);
  if (declare) declare(decl);
  decl.finalize();
  auto checkValueType = [&](const PortDecl& p) {
    auto [it, inserted] = valueTypes_.emplace(std::string(p.type->name), p.type);
    if (!inserted && it->second != p.type)
      throw std::logic_error("node type \"" + typeName + "\": value type name \"" +
                             std::string(p.type->name) + "\" is used by two different C++ types");
  };
  for (const PortDecl& p : decl.inputs()) checkValueType(p);
  for (const PortDecl& p : decl.outputs()) checkValueType(p);
  auto type = std::make_unique<NodeType>(std::move(decl), std::move(cook));
  const NodeType& ref = *type;
  types_.emplace(std::move(typeName), std::move(type));
  return ref;
}

const NodeType* NodeRegistry::find(std::string_view typeName) const {
  auto it = types_.find(typeName);
  return it == types_.end() ? nullptr : it->second.get();
}

const NodeType& NodeRegistry::get(std::string_view typeName) const {
  if (const NodeType* t = find(typeName)) return *t;
  std::string message = "unknown node type \"" + std::string(typeName) + "\"";
  if (std::string s = suggest(typeName); !s.empty()) message += " (did you mean \"" + s + "\"?)";
  throw GraphError(message);
}

std::vector<const NodeType*> NodeRegistry::types() const {
  std::vector<const NodeType*> out;
  for (const auto& [name, type] : types_) out.push_back(type.get());
  return out;
}

std::string NodeRegistry::suggest(std::string_view typeName) const {
  std::string best;
  std::size_t bestDistance = 4;
  for (const auto& [name, type] : types_) {
    std::size_t d = editDistance(typeName, name);
    if (d < bestDistance) {
      bestDistance = d;
      best = name;
    }
  }
  return best;
}

}  // namespace tfd::graph
