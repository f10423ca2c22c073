// STL writer, ASCII or binary (see io/mesh/surface_writers.h).
#include "io/mesh/surface_writers.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/mesh/surface_writer_common.h"

namespace tfd::io {

using detail::appendXyz;
using detail::checkIndices;

void writeStl(const std::filesystem::path& path, const core::SurfaceMesh& mesh, bool binary) {
  checkIndices(path, mesh);
  auto normalOf = [&](const std::array<int, 3>& t) {
    const core::Vec3& a = mesh.positions[t[0]];
    const core::Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    const double len = n.norm();
    return len > 0 ? core::Vec3(n / len) : core::Vec3::Zero();
  };
  std::string out;
  if (binary) {
    if (mesh.triangles.size() > 0xffffffffull) {
      throw core::Error("cannot write '" + path.string() + "': too many triangles for STL");
    }
    out.assign(80, ' ');
    out.replace(0, 19, "binary STL from tfd");
    appendScalar<std::uint32_t>(out, std::uint32_t(mesh.triangles.size()), Endian::Little);
    out.reserve(84 + 50 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
      const core::Vec3 n = normalOf(t);
      for (int i = 0; i < 3; ++i) appendScalar<float>(out, float(n[i]), Endian::Little);
      for (int v : t) {
        for (int i = 0; i < 3; ++i) {
          appendScalar<float>(out, float(mesh.positions[v][i]), Endian::Little);
        }
      }
      appendScalar<std::uint16_t>(out, 0, Endian::Little);
    }
  } else {
    out = "solid tfd\n";
    for (const auto& t : mesh.triangles) {
      out += "  facet normal ";
      appendXyz(out, normalOf(t));
      out += "\n    outer loop\n";
      for (int v : t) {
        out += "      vertex ";
        appendXyz(out, mesh.positions[v]);
        out += '\n';
      }
      out += "    endloop\n  endfacet\n";
    }
    out += "endsolid tfd\n";
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
