#include "graph/paths.h"

#include <algorithm>
#include <cctype>
#include <sstream>

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

std::string outputExtensionProblem(const ParamDecl& decl, const std::string& value) {
  if (!decl.isOutputFile() || value.empty()) return {};
  auto lower = [](std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  const std::string name = lower(fs::path(value).filename().string());
  std::istringstream patterns(decl.fileFilter);
  std::vector<std::string> extensions;
  for (std::string pattern; patterns >> pattern;) {
    if (!pattern.starts_with("*.")) return {};  // not a plain extension list: no check
    const std::string ext = lower(pattern.substr(1));
    if (name.size() > ext.size() && name.ends_with(ext)) return {};
    extensions.push_back(pattern.substr(1));
  }
  if (extensions.empty()) return {};
  std::string list;
  for (std::size_t i = 0; i < extensions.size(); ++i)
    list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
  return "'" + fs::path(value).filename().string() + "' does not end in " + list +
         ", the kind of file this node writes";
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
