// PLY writer, ASCII or binary (see io/mesh/surface_writers.h).
#include "io/mesh/surface_writers.h"

#include <cstdint>
#include <string>

#include "io/file_bytes.h"
#include "io/mesh/surface_writer_common.h"
#include "io/text_format.h"

namespace tfd::io {

using detail::appendXyz;
using detail::checkIndices;

void writePly(const std::filesystem::path& path, const core::SurfaceMesh& mesh,
              PlyEncoding encoding) {
  checkIndices(path, mesh);
  std::string out = "ply\nformat ";
  out += encoding == PlyEncoding::Ascii                ? "ascii"
         : encoding == PlyEncoding::BinaryLittleEndian ? "binary_little_endian"
                                                       : "binary_big_endian";
  out += " 1.0\ncomment written by tfd\nelement vertex ";
  appendNumber(out, mesh.positions.size());
  out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  appendNumber(out, mesh.triangles.size());
  out += "\nproperty list uchar int vertex_indices\nend_header\n";
  if (encoding == PlyEncoding::Ascii) {
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
  } else {
    const Endian e = encoding == PlyEncoding::BinaryLittleEndian ? Endian::Little : Endian::Big;
    out.reserve(out.size() + mesh.positions.size() * 24 + mesh.triangles.size() * 13);
    for (const auto& p : mesh.positions) {
      for (int i = 0; i < 3; ++i) appendScalar<double>(out, p[i], e);
    }
    for (const auto& t : mesh.triangles) {
      out += char(3);
      for (int v : t) appendScalar<std::int32_t>(out, v, e);
    }
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
