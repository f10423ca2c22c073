#include "graph/paths.h"

namespace tfd::graph {

namespace fs = std::filesystem;

PathContext makePathContext(const Graph& graph, const fs::path& outDir, const fs::path& baseDir) {
  PathContext ctx;
  if (!baseDir.empty())
    ctx.baseDir = fs::absolute(baseDir);
  else if (!graph.sourcePath().empty())
    ctx.baseDir = fs::absolute(graph.sourcePath()).parent_path();
  else
    ctx.baseDir = fs::current_path();
  ctx.baseDir = ctx.baseDir.lexically_normal();
  ctx.outDir = outDir.empty() ? ctx.baseDir : fs::absolute(outDir).lexically_normal();
  return ctx;
}

std::string resolvePath(const ParamDecl& decl, const std::string& value, const PathContext& ctx) {
  if (!decl.isPath() || value.empty()) return value;
  fs::path p(value);
  if (p.is_absolute()) return p.lexically_normal().string();
  const fs::path& base = decl.isOutputFile() ? ctx.outDir : ctx.baseDir;
  return (base / p).lexically_normal().string();
}

std::vector<ParamValue> resolvedParams(const Node& node, const PathContext& ctx) {
  const auto& decls = node.decl().params();
  std::vector<ParamValue> out;
  out.reserve(decls.size());
  for (std::size_t i = 0; i < decls.size(); ++i) {
    const ParamValue& v = node.paramAt(i);
    if (decls[i].isPath())
      out.push_back(resolvePath(decls[i], std::get<std::string>(v), ctx));
    else
      out.push_back(v);
  }
  return out;
}

}  // namespace tfd::graph
