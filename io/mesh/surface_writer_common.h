#pragma once
// Shared by the surface writers (off_writer.cpp, obj_writer.cpp, ply_writer.cpp, stl_writer.cpp):
// coordinates as shortest round-trip text, and the index check every writer runs first.
#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/surface/surface_mesh.h"
#include "io/text_format.h"

namespace tfd::io::detail {

inline void appendXyz(std::string& out, const core::Vec3& p) {
  appendNumber(out, p.x());
  out += ' ';
  appendNumber(out, p.y());
  out += ' ';
  appendNumber(out, p.z());
}

/// Throws core::Error naming the file and the first triangle with a vertex out of range.
inline void checkIndices(const std::filesystem::path& path, const core::SurfaceMesh& mesh) {
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

}  // namespace tfd::io::detail
