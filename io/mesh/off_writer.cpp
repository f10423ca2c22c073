// OFF writer (see io/mesh/surface_writers.h).
#include "io/mesh/surface_writers.h"

#include "io/file_bytes.h"
#include "io/mesh/surface_writer_common.h"
#include "io/text_format.h"

namespace tfd::io {

using detail::appendXyz;
using detail::checkIndices;

void writeOff(const std::filesystem::path& path, const core::SurfaceMesh& mesh) {
  checkIndices(path, mesh);
  std::string out = "OFF\n";
  appendNumber(out, mesh.positions.size());
  out += ' ';
  appendNumber(out, mesh.triangles.size());
  out += " 0\n";
  for (const auto& p : mesh.positions) {
    appendXyz(out, p);
    out += '\n';
  }
  for (const auto& t : mesh.triangles) {
    out += '3';
    for (int v : t) {
      out += ' ';
      appendNumber(out, v);
    }
    out += '\n';
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
