#include "ui/document/graph_clipboard.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "graph/graph_file.h"
#include "ui/document/node_ui.h"

namespace tfd::ui {

namespace {

void copyNodeContent(graph::Graph& target, const graph::Node& from, const std::string& name) {
  const auto& decls = from.decl().params();
  for (std::size_t i = 0; i < decls.size(); ++i)
    if (from.isSet(i)) target.setParam(name, decls[i].name, from.paramAt(i));
  target.setUi(name, from.ui());
}

std::string freeName(const graph::Graph& graph, const std::string& wanted) {
  if (!graph.findNode(wanted)) return wanted;
  std::string base = wanted;
  while (!base.empty() && std::isdigit(static_cast<unsigned char>(base.back()))) base.pop_back();
  if (base.empty()) base = "node";
  return graph.uniqueName(base);
}

}  // namespace

graph::Graph extractNodes(const graph::Graph& graph, const std::vector<std::string>& names) {
  std::set<std::string, std::less<>> wanted(names.begin(), names.end());
  for (const std::string& n : wanted) (void)graph.node(n);  // unknown names throw
  graph::Graph out(graph.registry());
  for (const graph::Node& n : graph.nodes()) {
    if (!wanted.count(n.name())) continue;
    out.addNode(n.type().name(), n.name());
    copyNodeContent(out, n, n.name());
  }
  for (const graph::Link& l : graph.links())
    if (wanted.count(l.from.node) && wanted.count(l.to.node)) out.connect(l.from, l.to);
  return out;
}

std::vector<std::string> mergeNodes(graph::Graph& target, const graph::Graph& pasted,
                                    QPointF offset) {
  std::map<std::string, std::string> renamed;
  std::vector<std::string> added;
  for (const graph::Node& n : pasted.nodes()) {
    const std::string name = freeName(target, n.name());
    target.addNode(n.type().name(), name);
    copyNodeContent(target, n, name);
    target.setUi(name, withDisplayFlag(withPosition(n.ui(), nodePosition(n) + offset), false));
    renamed[n.name()] = name;
    added.push_back(name);
  }
  for (const graph::Link& l : pasted.links())
    target.connect({renamed.at(l.from.node), l.from.port}, {renamed.at(l.to.node), l.to.port});
  return added;
}

graph::Graph parseClipboard(std::string_view text, const graph::NodeRegistry& registry) {
  return graph::parseGraph(text, registry, "clipboard");
}

}  // namespace tfd::ui
