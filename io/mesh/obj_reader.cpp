// Wavefront OBJ reader (see io/mesh/surface_readers.h).
#include <string>
#include <vector>

#include "core/error.h"
#include "io/mesh/surface_readers.h"
#include "io/text_scanner.h"

namespace tfd::io {

core::SurfaceMesh readObj(const std::filesystem::path& path) {
  const std::string text = readFileBytes(path);
  TextScanner s(text, path.string());
  core::SurfaceMesh mesh;
  std::vector<int> corners;
  while (s.nextLine()) {
    const std::string_view keyword = s.token();
    if (keyword == "v") {
      const std::string number = std::to_string(mesh.positions.size() + 1);
      const std::string where = " of vertex " + number;
      core::Vec3 p;
      p.x() = s.number("coordinate x" + where);
      p.y() = s.number("coordinate y" + where);
      p.z() = s.number("coordinate z" + where);
      int extra = 0;
      while (!s.atLineEnd()) {
        s.number("a weight or colour value" + where);
        ++extra;
      }
      if (extra != 0 && extra != 1 && extra != 3) {
        s.fail("vertex " + number + " has " + std::to_string(3 + extra) +
               " values; expected x y z, x y z w or x y z r g b");
      }
      mesh.positions.push_back(p);
    } else if (keyword == "f") {
      corners.clear();
      const long long defined = (long long)mesh.positions.size();
      while (!s.atLineEnd()) {
        const std::string_view corner = s.token();
        const std::string_view vertex = corner.substr(0, corner.find('/'));
        long long index;
        if (!parseInteger(vertex, index)) {
          s.fail("expected a vertex index (v, v/vt, v/vt/vn or v//vn), found " +
                 describeToken(corner));
        }
        // Texture and normal indices must be integers too when present.
        for (std::size_t slash = corner.find('/'); slash != std::string_view::npos;) {
          const std::size_t next = corner.find('/', slash + 1);
          const std::string_view part =
              corner.substr(slash + 1, next == std::string_view::npos ? std::string_view::npos
                                                                      : next - slash - 1);
          long long ignored;
          if (!part.empty() && !parseInteger(part, ignored)) {
            s.fail("expected texture/normal indices in " + describeToken(corner));
          }
          slash = next;
        }
        if (index == 0) s.fail("vertex index 0 is invalid (OBJ indices start at 1)");
        const long long zeroBased = index > 0 ? index - 1 : defined + index;
        if (zeroBased < 0 || zeroBased >= defined) {
          s.fail("face uses vertex " + std::to_string(index) + " but " + std::to_string(defined) +
                 " vertices are defined so far");
        }
        corners.push_back(int(zeroBased));
      }
      if (corners.size() < 3) {
        s.fail("a face needs at least 3 vertices, found " + std::to_string(corners.size()));
      }
      for (std::size_t i = 2; i < corners.size(); ++i) {
        mesh.triangles.push_back({corners[0], corners[i - 1], corners[i]});
      }
    }
    // Other statements (vt, vn, vp, o, g, s, usemtl, mtllib, l, p, ...) carry no geometry
    // we use.
  }
  if (mesh.triangles.empty()) {
    throw core::Error("file '" + path.string() + "': the mesh has no faces ('f' lines)");
  }
  return mesh;
}

}  // namespace tfd::io
