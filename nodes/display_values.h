#pragma once
// What a viewport or `tfd render` shows for a node: the drawable values of its cooked outputs
// (a mesh, a field, degenerate curves, traced lines, design elements), completed from upstream
// where the node itself holds no geometry (curves are drawn inside the boundary of the mesh they
// came from). The display node is the one whose ui object carries {"display": true} (the editor's
// display flag, Houdini's habit), else the last node in file order that has outputs.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/evaluator.h"
#include "graph/graph.h"
#include "nodes/value_types.h"

namespace tfd::nodes {

/// The key of the display flag in a node's ui object.
inline constexpr const char* kDisplayFlagKey = "display";

bool hasDisplayFlag(const graph::Node& node);
/// The flagged node, else the last node with outputs, else the last node; "" for an empty graph.
std::string displayNodeName(const graph::Graph& graph);

struct DisplayValues {
  std::shared_ptr<const core::TetMesh> mesh;       ///< boundary to draw (may come from upstream)
  std::shared_ptr<const core::TensorField> field;  ///< for a cutting plane
  std::shared_ptr<const core::DegenerateCurves> curves;
  std::shared_ptr<const core::Polylines> lines;
  std::vector<std::shared_ptr<const core::ConstraintSet>> constraints;
  bool empty() const { return !mesh && !field && !curves && !lines && constraints.empty(); }
};

/// The values to draw for `node` after `result` (values of nodes that did not cook are missing).
/// The node's own outputs come first; a sink (no outputs) shows what is linked into it. Missing
/// pieces are taken from the nearest upstream node that has them: the field and mesh, and the
/// design elements that reach the node (the most downstream constraint outputs, so merged sets
/// are not drawn twice).
DisplayValues displayValues(const graph::Graph& graph, const graph::CookResult& result,
                            std::string_view node);

}  // namespace tfd::nodes
