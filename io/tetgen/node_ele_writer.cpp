// TetGen .node/.ele writer (io/tetgen/node_ele.h).
#include <string>

#include "io/file_bytes.h"
#include "io/tetgen/node_ele.h"
#include "io/text_format.h"

namespace tfd::io {

namespace fs = std::filesystem;

void writeTetgen(const fs::path& path, const core::TetMesh& mesh) {
  const fs::path base = detail::tetgenBase(path);
  std::string node = "# written by tfd\n";
  appendNumber(node, mesh.vertexCount());
  node += " 3 0 0\n";
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    appendNumber(node, v + 1);
    for (int k = 0; k < 3; ++k) {
      node += ' ';
      appendNumber(node, mesh.positions()[v][k]);
    }
    node += '\n';
  }
  std::string ele = "# written by tfd\n";
  appendNumber(ele, mesh.tetCount());
  ele += " 4 0\n";
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    appendNumber(ele, t + 1);
    for (int v : mesh.tets()[t]) {
      ele += ' ';
      appendNumber(ele, v + 1);
    }
    ele += '\n';
  }
  writeFileBytes(detail::withExtension(base, ".node"), node);
  writeFileBytes(detail::withExtension(base, ".ele"), ele);
}

}  // namespace tfd::io
