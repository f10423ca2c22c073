// MergeConstraints: several constraint sets into one, in link order.
#include "graph/node_registry.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc("Merges design constraints (points and curves) into one set, in link order.")
      .category("Design");
  d.input<core::ConstraintSet>("constraints").multiple().doc("Any number of constraint sets.");
  d.output<core::ConstraintSet>("constraints").doc("All inputs' elements, in link order.");
}

void cook(graph::CookContext& c) {
  auto merged = std::make_shared<core::ConstraintSet>();
  for (const auto& set : c.inputs<core::ConstraintSet>("constraints")) {
    merged->points.insert(merged->points.end(), set->points.begin(), set->points.end());
    merged->curves.insert(merged->curves.end(), set->curves.begin(), set->curves.end());
  }
  c.info(std::to_string(merged->points.size()) + " point and " +
         std::to_string(merged->curves.size()) + " curve constraints");
  c.setOutput("constraints", std::move(merged));
}

}  // namespace

void registerMergeConstraints(graph::NodeRegistry& r) {
  r.add("MergeConstraints", 1, declare, cook);
}

}  // namespace tfd::nodes
