#include "io/mesh/surface_writers.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/text_format.h"

namespace tfd::io {
namespace {

void appendXyz(std::string& out, const core::Vec3& p) {
  appendNumber(out, p.x());
  out += ' ';
  appendNumber(out, p.y());
  out += ' ';
  appendNumber(out, p.z());
}

void checkIndices(const std::filesystem::path& path, const core::SurfaceMesh& mesh) {
  const int n = int(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int v : mesh.triangles[t]) {
      if (v < 0 || v >= n) {
        throw core::Error("cannot write '" + path.string() + "': triangle " + std::to_string(t) +
                          " uses vertex " + std::to_string(v) + ", out of range");
      }
    }
  }
}

}  // namespace

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
