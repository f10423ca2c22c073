// OFF reader (see io/mesh/surface_readers.h).
#include <algorithm>
#include <string>

#include "core/error.h"
#include "io/mesh/surface_readers.h"
#include "io/text_scanner.h"

namespace tfd::io {

core::SurfaceMesh readOff(const std::filesystem::path& path) {
  const std::string text = readFileBytes(path);
  TextScanner s(text, path.string());
  if (!s.nextLine()) s.failAtEnd("the file is empty, expected the header 'OFF'");
  const std::string_view header = s.token();
  // Variants with colours (C) or normals (N) carry extra values per vertex.
  const bool extraVertexValues =
      header == "COFF" || header == "NOFF" || header == "CNOFF" || header == "NCOFF";
  if (header != "OFF" && !extraVertexValues) {
    s.fail("expected the header 'OFF', found " + describeToken(header));
  }
  if (s.atLineEnd() && !s.nextLine()) {
    s.failAtEnd("expected the counts 'vertices faces edges' after the header");
  }
  const long long nv = s.integer("the vertex count");
  const long long nf = s.integer("the face count");
  if (!s.atLineEnd()) s.integer("the edge count");
  s.expectLineEnd("the counts");
  if (nv < 0 || nf < 0) s.fail("negative vertex or face count");
  if (nv > (long long)text.size() || nf > (long long)text.size()) {
    s.fail("the counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
           " faces) cannot fit in a file of " + std::to_string(text.size()) + " bytes");
  }

  core::SurfaceMesh mesh;
  mesh.positions.reserve(nv);
  for (long long v = 0; v < nv; ++v) {
    if (!s.nextLine()) {
      s.failAtEnd("expected " + std::to_string(nv) + " vertices, found " + std::to_string(v));
    }
    const std::string where = " of vertex " + std::to_string(v);
    core::Vec3 p;
    p.x() = s.number("coordinate x" + where);
    p.y() = s.number("coordinate y" + where);
    p.z() = s.number("coordinate z" + where);
    if (!extraVertexValues) s.expectLineEnd("the 3 coordinates" + where);
    mesh.positions.push_back(p);
  }
  mesh.triangles.reserve(nf);
  for (long long f = 0; f < nf; ++f) {
    if (!s.nextLine()) {
      s.failAtEnd("expected " + std::to_string(nf) + " faces, found " + std::to_string(f));
    }
    const long long k = s.integer("the vertex count of face " + std::to_string(f));
    if (k < 3) {
      s.fail("face " + std::to_string(f) + " has " + std::to_string(k) +
             " vertices; a face needs at least 3");
    }
    int first = -1, previous = -1;
    for (long long i = 0; i < k; ++i) {
      const long long index =
          s.integer("vertex " + std::to_string(i) + " of face " + std::to_string(f));
      if (index < 0 || index >= nv) {
        s.fail("face " + std::to_string(f) + " uses vertex " + std::to_string(index) +
               ", out of range [0, " + std::to_string(nv) + ")");
      }
      if (i == 0) {
        first = int(index);
      } else if (i >= 2) {
        mesh.triangles.push_back({first, previous, int(index)});
      }
      previous = int(index);
    }
    // Anything left is a face colour, which we ignore.
  }
  if (s.nextLine()) {
    s.fail("unexpected " + describeToken(s.token()) + " after the last face");
  }
  if (mesh.triangles.empty()) {
    throw core::Error("file '" + path.string() + "': the mesh has no faces");
  }
  return mesh;
}

}  // namespace tfd::io
