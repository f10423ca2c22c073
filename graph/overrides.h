#pragma once
// Parameter overrides from the command line: `tfd cook g.tfd.json --set prop1.tolerance=1e-6`.
// The value text is parsed per the parameter's kind (paramFromText): plain for numbers,
// strings and bools, JSON for vectors (`--set p1.position=[0.1,0,0]`).
#include <string>
#include <string_view>

#include "graph/graph.h"

namespace tfd::graph {

struct ParamOverride {
  std::string node, param, value;
};

/// Splits "NODE.PARAM=VALUE" (at the first '.' and the first '=' after it). Throws GraphError
/// "--set: expected NODE.PARAM=VALUE, found \"...\"".
ParamOverride parseOverride(std::string_view text);

/// Sets the parameter. Throws GraphError naming the override, node and parameter, e.g.
/// `--set p1.radius=-1: parameter "radius" of node "p1" (Sphere): expected a number >= 0,
/// found -1`.
void applyOverride(Graph& graph, const ParamOverride& override);

}  // namespace tfd::graph
