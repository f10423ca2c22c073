#include "graph/overrides.h"

#include "graph/errors.h"

namespace tfd::graph {

ParamOverride parseOverride(std::string_view text) {
  const auto dot = text.find('.');
  const auto eq = text.find('=', dot == std::string_view::npos ? 0 : dot);
  if (dot == std::string_view::npos || eq == std::string_view::npos || dot == 0 || eq == dot + 1)
    throw GraphError("--set: expected NODE.PARAM=VALUE, found \"" + std::string(text) + "\"");
  return ParamOverride{std::string(text.substr(0, dot)),
                       std::string(text.substr(dot + 1, eq - dot - 1)),
                       std::string(text.substr(eq + 1))};
}

void applyOverride(Graph& graph, const ParamOverride& o) {
  const std::string prefix = "--set " + o.node + "." + o.param + "=" + o.value + ": ";
  try {
    const Node& node = graph.node(o.node);
    const ParamDecl* decl = node.decl().findParam(o.param);
    if (!decl) (void)node.param(o.param);  // throws "has no parameter", listing them
    ParamValue value;
    try {
      value = paramFromText(*decl, o.value);
    } catch (const GraphError& e) {
      throw GraphError("parameter \"" + o.param + "\" of node \"" + o.node + "\" (" +
                       node.type().name() + "): " + e.what());
    }
    graph.setParam(o.node, o.param, std::move(value));
  } catch (const GraphError& e) {
    throw GraphError(prefix + e.what());
  }
}

}  // namespace tfd::graph
