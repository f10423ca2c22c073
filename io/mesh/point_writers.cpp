#include "io/mesh/point_writers.h"

#include <charconv>
#include <cstdint>
#include <string>

#include "io/binary_io.h"
#include "io/file_bytes.h"
#include "io/text_format.h"

namespace tfd::io {

void writeInstancePointsPly(const std::filesystem::path& path, const core::InstancePoints& points,
                            PlyEncoding encoding) {
  std::string out = "ply\nformat ";
  out += encoding == PlyEncoding::Ascii                ? "ascii"
         : encoding == PlyEncoding::BinaryLittleEndian ? "binary_little_endian"
                                                       : "binary_big_endian";
  out += " 1.0\ncomment tfd instance points: orient is Houdini's (x, y, z, w) quaternion\n";
  out += "element vertex ";
  appendNumber(out, points.points.size());
  out +=
      "\nproperty double x\nproperty double y\nproperty double z\n"
      "property float orient_x\nproperty float orient_y\nproperty float orient_z\n"
      "property float orient_w\nproperty float pscale\nproperty float scale_x\n"
      "property float scale_y\nproperty float scale_z\nproperty uchar kind\nend_header\n";
  for (const core::InstancePoint& p : points.points) {
    // Houdini's component order: (x, y, z, w); InstancePoint stores (w, x, y, z).
    const float floats[8] = {float(p.orient[1]), float(p.orient[2]),        float(p.orient[3]),
                             float(p.orient[0]), float(p.scale.maxCoeff()), float(p.scale[0]),
                             float(p.scale[1]),  float(p.scale[2])};
    const auto kind = std::uint8_t(p.kind);
    if (encoding == PlyEncoding::Ascii) {
      for (int i = 0; i < 3; ++i) {
        appendNumber(out, p.position[i]);
        out += ' ';
      }
      for (float f : floats) {
        char buffer[32];
        const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, f);
        out.append(buffer, end);
        out += ' ';
      }
      appendNumber(out, int(kind));
      out += '\n';
    } else {
      const Endian e = encoding == PlyEncoding::BinaryLittleEndian ? Endian::Little : Endian::Big;
      for (int i = 0; i < 3; ++i) appendScalar<double>(out, p.position[i], e);
      for (float f : floats) appendScalar<float>(out, f, e);
      out += char(kind);
    }
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
