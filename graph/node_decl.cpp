#include "graph/node_decl.h"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "graph/errors.h"

namespace tfd::graph {

namespace {

template <class C>
int indexOf(const C& items, std::string_view name) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) return static_cast<int>(i);
  return -1;
}

bool isIdentifier(std::string_view s) {
  if (s.empty() || s.size() > 64) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(s[0])) return false;
  return std::all_of(s.begin(), s.end(),
                     [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

}  // namespace

int NodeDecl::inputIndex(std::string_view name) const { return indexOf(inputs_, name); }
int NodeDecl::outputIndex(std::string_view name) const { return indexOf(outputs_, name); }
int NodeDecl::paramIndex(std::string_view name) const { return indexOf(params_, name); }

const PortDecl* NodeDecl::findInput(std::string_view name) const {
  int i = inputIndex(name);
  return i < 0 ? nullptr : &inputs_[i];
}
const PortDecl* NodeDecl::findOutput(std::string_view name) const {
  int i = outputIndex(name);
  return i < 0 ? nullptr : &outputs_[i];
}
const ParamDecl* NodeDecl::findParam(std::string_view name) const {
  int i = paramIndex(name);
  return i < 0 ? nullptr : &params_[i];
}

const ParamMigration* NodeDecl::migrationFrom(int fromVersion) const {
  auto it = migrations_.find(fromVersion);
  return it == migrations_.end() ? nullptr : &it->second;
}

void NodeDecl::finalize() {
  auto fail = [&](const std::string& what) {
    throw std::logic_error("node type \"" + typeName_ + "\": " + what);
  };
  if (!isIdentifier(typeName_)) fail("the type name must be an identifier");
  if (typeVersion_ < 1) fail("typeVersion must be >= 1");
  auto checkPorts = [&](const std::deque<PortDecl>& ports, const char* kind, bool isInput) {
    std::set<std::string> seen;
    for (const PortDecl& p : ports) {
      if (!isIdentifier(p.name)) fail(std::string(kind) + " '" + p.name + "': not an identifier");
      if (!seen.insert(p.name).second) fail(std::string("duplicate ") + kind + " '" + p.name + "'");
      if (!p.type) fail(std::string(kind) + " '" + p.name + "' has no value type");
      if (!isInput && (p.optional || p.multiple))
        fail("output '" + p.name + "' cannot be optional or multiple");
    }
  };
  checkPorts(inputs_, "input", true);
  checkPorts(outputs_, "output", false);
  std::set<std::string> seen;
  for (ParamDecl& p : params_) {
    const std::string where = "parameter '" + p.name + "'";
    if (!isIdentifier(p.name)) fail(where + ": not an identifier");
    if (!seen.insert(p.name).second) fail("duplicate " + where);
    if (!p.choices.empty() && p.kind != ParamKind::String && p.kind != ParamKind::StringList)
      fail(where + ": choices need a string or string-list parameter");
    if (!p.choices.empty() && p.kind == ParamKind::String) {
      if (std::get<std::string>(p.defaultValue).empty() &&
          std::find(p.choices.begin(), p.choices.end(), "") == p.choices.end())
        p.defaultValue = p.choices.front();
    }
    if (p.isPath() && p.kind != ParamKind::String) fail(where + ": file hints need a string");
    if (p.size && p.kind != ParamKind::DoubleList) fail(where + ": size() needs a double list");
    if (p.kind == ParamKind::DoubleList && p.size &&
        std::get<std::vector<double>>(p.defaultValue).empty())
      p.defaultValue = std::vector<double>(*p.size, std::max(0.0, p.min.value_or(0.0)));
    if (p.min && p.max && *p.min > *p.max) fail(where + ": min > max");
    try {
      p.defaultValue = checkParamValue(p, p.defaultValue);
    } catch (const GraphError& e) {
      fail(where + ": default value: " + e.what());
    }
  }
  for (const auto& [from, fn] : migrations_)
    if (from < 1 || from >= typeVersion_ || !fn)
      fail("migration from typeVersion " + std::to_string(from) + " is outside [1, " +
           std::to_string(typeVersion_ - 1) + "]");
}

}  // namespace tfd::graph
