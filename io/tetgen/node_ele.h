#pragma once
// TetGen .node/.ele tet-mesh files.
// Every tet-mesh reader follows the conventions of io/tet_mesh_build.h.
#include <filesystem>
#include <memory>
#include <string>

#include "core/tet_mesh.h"

namespace tfd::io {

namespace detail {
/// base.node / base.ele for a path naming either file or the base.
inline std::filesystem::path tetgenBase(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".node" || ext == ".ele") return std::filesystem::path(path).replace_extension();
  return path;
}
inline std::filesystem::path withExtension(const std::filesystem::path& base, const char* ext) {
  return std::filesystem::path(base.string() + ext);
}
}  // namespace detail

/// TetGen files. `path` is the .node file, the .ele file or their common base name; both are
/// read. Numbering starts at 0 or 1 as the first point of the .node file says; point and tet
/// attributes and boundary markers are ignored.
std::shared_ptr<const core::TetMesh> readTetgen(const std::filesystem::path& path);
/// Writes base.node and base.ele (1-based, no attributes) for `path` = base, base.node or
/// base.ele; each file is written atomically.
void writeTetgen(const std::filesystem::path& path, const core::TetMesh& mesh);

}  // namespace tfd::io
