#include "graph/graph.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "graph/errors.h"

namespace tfd::graph {

namespace {

std::string nodeLabel(const Node& n) {
  return "node \"" + n.name() + "\" (" + n.type().name() + ")";
}

template <class C>
std::string nameList(const C& items) {
  if (items.empty()) return "none";
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item.name;
  return out;
}

}  // namespace

Endpoint Endpoint::parse(std::string_view text) {
  auto dot = text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == text.size())
    throw GraphError("expected \"node.port\", found \"" + std::string(text) + "\"");
  return Endpoint{std::string(text.substr(0, dot)), std::string(text.substr(dot + 1))};
}

const ParamValue& Node::param(std::string_view name) const {
  int i = decl().paramIndex(name);
  if (i < 0)
    throw GraphError(nodeLabel(*this) + " has no parameter \"" + std::string(name) +
                     "\" (parameters: " + nameList(decl().params()) + ")");
  return paramAt(static_cast<std::size_t>(i));
}

const ParamValue& Node::paramAt(std::size_t index) const {
  return overrides_[index] ? *overrides_[index] : decl().params()[index].defaultValue;
}

bool Graph::isValidNodeName(std::string_view name) {
  if (name.empty() || name.size() > 64) return false;
  auto ok = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(), ok);
}

std::string Graph::uniqueName(std::string_view base) const {
  for (int n = 1;; ++n) {
    std::string candidate = std::string(base) + std::to_string(n);
    if (!findNode(candidate)) return candidate;
  }
}

const Node& Graph::addNode(std::string_view typeName, std::string_view name) {
  const NodeType& type = registry_->get(typeName);
  std::string chosen(name);
  if (chosen.empty()) {
    std::string base = type.name();
    std::transform(base.begin(), base.end(), base.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    chosen = uniqueName(base);
  }
  if (!isValidNodeName(chosen))
    throw GraphError("invalid node name \"" + chosen +
                     "\" (use 1-64 letters, digits, '_' or '-', starting with a letter or '_')");
  if (findNode(chosen)) throw GraphError("a node named \"" + chosen + "\" already exists");
  Node n;
  n.name_ = chosen;
  n.type_ = &type;
  n.overrides_.resize(type.decl().params().size());
  nodes_.push_back(std::move(n));
  index_[chosen] = static_cast<int>(nodes_.size()) - 1;
  ++revision_;
  return nodes_.back();
}

void Graph::removeNode(std::string_view name) {
  int i = nodeIndex(name);
  if (i < 0) throw GraphError("unknown node \"" + std::string(name) + "\"");
  std::erase_if(links_, [&](const Link& l) { return l.from.node == name || l.to.node == name; });
  nodes_.erase(nodes_.begin() + i);
  rebuildIndex();
  ++revision_;
}

void Graph::renameNode(std::string_view from, std::string_view to) {
  Node& n = mutableNode(from);
  if (from == to) return;
  if (!isValidNodeName(to)) throw GraphError("invalid node name \"" + std::string(to) + "\"");
  if (findNode(to)) throw GraphError("a node named \"" + std::string(to) + "\" already exists");
  const std::string old = n.name_;
  n.name_ = std::string(to);
  for (Link& l : links_) {
    if (l.from.node == old) l.from.node = n.name_;
    if (l.to.node == old) l.to.node = n.name_;
  }
  rebuildIndex();
  ++revision_;
}

int Graph::nodeIndex(std::string_view name) const {
  auto it = index_.find(name);
  return it == index_.end() ? -1 : it->second;
}

const Node* Graph::findNode(std::string_view name) const {
  int i = nodeIndex(name);
  return i < 0 ? nullptr : &nodes_[i];
}

const Node& Graph::node(std::string_view name) const {
  if (const Node* n = findNode(name)) return *n;
  throw GraphError("unknown node \"" + std::string(name) + "\"");
}

Node& Graph::mutableNode(std::string_view name) { return const_cast<Node&>(node(name)); }

void Graph::rebuildIndex() {
  index_.clear();
  for (std::size_t i = 0; i < nodes_.size(); ++i) index_[nodes_[i].name_] = static_cast<int>(i);
}

void Graph::setParam(std::string_view nodeName, std::string_view paramName, ParamValue value) {
  Node& n = mutableNode(nodeName);
  int i = n.decl().paramIndex(paramName);
  if (i < 0) (void)n.param(paramName);  // throws the "has no parameter" error
  const ParamDecl& d = n.decl().params()[i];
  try {
    value = checkParamValue(d, std::move(value));
  } catch (const GraphError& e) {
    throw GraphError("parameter \"" + d.name + "\" of " + nodeLabel(n) + ": " + e.what());
  }
  if (value == d.defaultValue)
    n.overrides_[i].reset();
  else
    n.overrides_[i] = std::move(value);
  ++revision_;
}

void Graph::resetParam(std::string_view nodeName, std::string_view paramName) {
  Node& n = mutableNode(nodeName);
  int i = n.decl().paramIndex(paramName);
  if (i < 0) (void)n.param(paramName);
  n.overrides_[i].reset();
  ++revision_;
}

const ParamValue& Graph::param(std::string_view nodeName, std::string_view paramName) const {
  return node(nodeName).param(paramName);
}

void Graph::setUi(std::string_view nodeName, Json ui) {
  if (!ui.is_object())
    throw GraphError("ui data of node \"" + std::string(nodeName) + "\" must be a JSON object");
  mutableNode(nodeName).ui_ = std::move(ui);
  ++revision_;
}

std::optional<std::string> Graph::checkEndpoint(const Endpoint& e, bool output) const {
  const Node* n = findNode(e.node);
  if (!n) return "unknown node \"" + e.node + "\"";
  const NodeDecl& d = n->decl();
  if (output ? d.findOutput(e.port) : d.findInput(e.port)) return std::nullopt;
  std::string message = nodeLabel(*n) + " has no " + (output ? "output" : "input") + " \"" +
                        e.port + "\" (" + (output ? "outputs: " : "inputs: ") +
                        nameList(output ? d.outputs() : d.inputs()) + ")";
  if (!output && d.findOutput(e.port)) message += "; \"" + e.port + "\" is an output";
  if (output && d.findInput(e.port)) message += "; \"" + e.port + "\" is an input";
  return message;
}

void Graph::connect(const Endpoint& from, const Endpoint& to) {
  if (auto why = checkEndpoint(from, true)) throw GraphError("link source: " + *why);
  if (auto why = checkEndpoint(to, false)) throw GraphError("link target: " + *why);
  const Node& a = node(from.node);
  const Node& b = node(to.node);
  const PortDecl& out = *a.decl().findOutput(from.port);
  const PortDecl& in = *b.decl().findInput(to.port);
  const std::string arrow = from.str() + " -> " + to.str();
  if (out.type != in.type)
    throw GraphError("cannot link " + arrow + ": output " + from.str() + " is " +
                     std::string(out.type->name) + " but input " + to.str() + " takes " +
                     std::string(in.type->name));
  for (const Link& l : links_) {
    if (l.to != to) continue;
    if (l.from == from) throw GraphError("duplicate link " + arrow);
    if (!in.multiple)
      throw GraphError("cannot link " + arrow + ": input " + to.str() +
                       " takes a single link and is already linked from " + l.from.str());
  }
  if (from.node == to.node)
    throw GraphError("link " + arrow + " would create a cycle: " + from.node + " -> " + from.node);
  std::vector<std::string> path = pathBetween(to.node, from.node);
  if (!path.empty()) {
    std::string cycle;
    for (const std::string& n : path) cycle += n + " -> ";
    throw GraphError("link " + arrow + " would create a cycle: " + cycle + to.node);
  }
  links_.push_back(Link{from, to});
  ++revision_;
}

bool Graph::disconnect(const Endpoint& from, const Endpoint& to) {
  auto it = std::find(links_.begin(), links_.end(), Link{from, to});
  if (it == links_.end()) return false;
  links_.erase(it);
  ++revision_;
  return true;
}

std::vector<Link> Graph::linksInto(std::string_view nodeName, std::string_view port) const {
  std::vector<Link> out;
  for (const Link& l : links_)
    if (l.to.node == nodeName && l.to.port == port) out.push_back(l);
  return out;
}

std::vector<std::string> Graph::pathBetween(const std::string& from, const std::string& to) const {
  // Breadth-first search along links (adjacency built once: O(links)); returns from ... to.
  std::map<std::string_view, std::vector<std::string_view>> next;
  for (const Link& l : links_) next[l.from.node].push_back(l.to.node);
  std::map<std::string_view, std::string_view> parent;
  std::vector<std::string_view> queue{from};
  parent[from] = from;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::string_view current = queue[head];
    if (current == to) {
      std::vector<std::string> path{to};
      while (path.back() != from) path.emplace_back(parent[path.back()]);
      std::reverse(path.begin(), path.end());
      return path;
    }
    if (auto it = next.find(current); it != next.end())
      for (std::string_view n : it->second)
        if (parent.emplace(n, current).second) queue.push_back(n);
  }
  return {};
}

}  // namespace tfd::graph
