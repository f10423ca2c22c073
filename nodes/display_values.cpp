#include "nodes/display_values.h"

#include <algorithm>
#include <deque>
#include <set>

namespace tfd::nodes {

namespace {

/// Fills the empty slots of `out` from value `v`; constraint sets are collected separately.
void take(DisplayValues& out, const graph::Value& v) {
  if (auto m = v.as<core::TetMesh>(); m && !out.mesh) out.mesh = m;
  if (auto f = v.as<core::TensorField>(); f && !out.field) out.field = f;
  if (auto c = v.as<core::DegenerateCurves>(); c && !out.curves) out.curves = c;
  if (auto l = v.as<core::Polylines>(); l && !out.lines) out.lines = l;
}

bool hasConstraintOutput(const graph::Node& n) {
  for (const graph::PortDecl& p : n.decl().outputs())
    if (p.type == graph::valueType<core::ConstraintSet>()) return true;
  return false;
}

}  // namespace

bool hasDisplayFlag(const graph::Node& node) {
  auto it = node.ui().find(kDisplayFlagKey);
  return it != node.ui().end() && it->is_boolean() && it->get<bool>();
}

std::string displayNodeName(const graph::Graph& graph) {
  for (const graph::Node& n : graph.nodes())
    if (hasDisplayFlag(n)) return n.name();
  for (auto it = graph.nodes().rbegin(); it != graph.nodes().rend(); ++it)
    if (!it->decl().outputs().empty()) return it->name();
  return graph.nodes().empty() ? "" : graph.nodes().back().name();
}

DisplayValues displayValues(const graph::Graph& graph, const graph::CookResult& result,
                            std::string_view node) {
  DisplayValues out;
  const graph::Node* start = graph.findNode(node);
  if (!start) return out;
  if (const graph::NodeReport* r = result.report(node))
    for (const graph::Value& v : r->outputs) {
      take(out, v);
      if (auto c = v.as<core::ConstraintSet>()) out.constraints.push_back(c);
    }
  // Breadth-first upstream: nearest producers first.
  std::deque<std::string> queue{std::string(node)};
  std::set<std::string> seen{std::string(node)};
  const bool ownConstraints = !out.constraints.empty();
  while (!queue.empty()) {
    const std::string current = queue.front();
    queue.pop_front();
    for (const graph::Link& l : graph.links()) {
      if (l.to.node != current) continue;
      const std::string& from = l.from.node;
      graph::Value v = result.output(from, l.from.port);
      take(out, v);
      // A constraint set consumed by a node that itself outputs constraints (a merge) is
      // already part of that node's set.
      if (auto c = v.as<core::ConstraintSet>();
          c && !ownConstraints && !hasConstraintOutput(graph.node(current)) &&
          std::find(out.constraints.begin(), out.constraints.end(), c) == out.constraints.end())
        out.constraints.push_back(c);
      if (seen.insert(from).second) queue.push_back(from);
    }
  }
  if (out.field) out.mesh = out.field->meshPtr();  // the boundary the field lives on
  return out;
}

}  // namespace tfd::nodes
