// OBJ writer (see io/mesh/surface_writers.h).
#include "io/mesh/surface_writers.h"

#include "io/file_bytes.h"
#include "io/mesh/surface_writer_common.h"
#include "io/text_format.h"

namespace tfd::io {

using detail::appendXyz;
using detail::checkIndices;

void writeObj(const std::filesystem::path& path, const core::SurfaceMesh& mesh) {
  checkIndices(path, mesh);
  std::string out = "# written by tfd\n";
  for (const auto& p : mesh.positions) {
    out += "v ";
    appendXyz(out, p);
    out += '\n';
  }
  for (const auto& t : mesh.triangles) {
    out += 'f';
    for (int v : t) {
      out += ' ';
      appendNumber(out, v + 1);
    }
    out += '\n';
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
