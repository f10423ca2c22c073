#include "graph/validation.h"

#include <filesystem>

#include "graph/json_text.h"

namespace tfd::graph {

std::vector<Issue> validateGraph(const Graph& graph, const PathContext& paths) {
  std::vector<Issue> issues;
  for (const Node& node : graph.nodes()) {
    const std::string where = pointerJoin("/nodes", node.name());
    for (const PortDecl& in : node.decl().inputs())
      if (!in.optional && graph.linksInto(node.name(), in.name).empty())
        issues.push_back({Severity::Error, node.name(), where,
                          "required input '" + in.name + "' is not connected"});
    const auto& decls = node.decl().params();
    for (std::size_t i = 0; i < decls.size(); ++i) {
      if (decls[i].isOutputFile()) {
        const std::string problem =
            outputExtensionProblem(decls[i], std::get<std::string>(node.paramAt(i)));
        if (!problem.empty())
          issues.push_back({Severity::Error, node.name(),
                            pointerJoin(where + "/params", decls[i].name),
                            "parameter '" + decls[i].name + "': " + problem});
      }
      if (!decls[i].isInputFile()) continue;
      const std::string& value = std::get<std::string>(node.paramAt(i));
      if (value.empty()) continue;
      const std::string resolved = resolvePath(decls[i], value, paths);
      std::error_code ec;
      if (!std::filesystem::exists(resolved, ec))
        issues.push_back({Severity::Warning, node.name(),
                          pointerJoin(where + "/params", decls[i].name),
                          "input file " + resolved + " does not exist"});
    }
  }
  return issues;
}

}  // namespace tfd::graph
