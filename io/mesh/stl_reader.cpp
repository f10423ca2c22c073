// STL reader, ASCII and binary, with exact welding (see io/mesh/surface_readers.h).
#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/surface/surface_weld.h"
#include "io/binary_io.h"
#include "io/mesh/surface_readers.h"
#include "io/text_scanner.h"

namespace tfd::io {
namespace {

/// STL repeats every corner per triangle: collect the soup, weld it once at the end
/// (core::weldCoincidentVertices).
void addTriangle(core::SurfaceMesh& mesh, const core::Vec3 (&v)[3]) {
  const int first = static_cast<int>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {v[0], v[1], v[2]});
  mesh.triangles.push_back({first, first + 1, first + 2});
}

void readBinary(const std::string& data, const std::string& file, core::SurfaceMesh& mesh) {
  const std::uint32_t count = loadScalar<std::uint32_t>(data.data() + 80, Endian::Little);
  mesh.positions.reserve(3 * std::size_t(count));
  mesh.triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* p = data.data() + 84 + std::size_t(t) * 50 + 12;  // skip the normal
    core::Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) v[k][i] = loadScalar<float>(p + 12 * k + 4 * i, Endian::Little);
      if (!v[k].allFinite()) {
        throw core::Error("file '" + file + "': triangle " + std::to_string(t) +
                          " has a non-finite coordinate");
      }
    }
    addTriangle(mesh, v);
  }
}

void readAscii(const std::string& data, const std::string& file, core::SurfaceMesh& mesh) {
  TextScanner s(data, file, 0);
  auto expect = [&](std::string_view word, std::string_view context) {
    if (!s.nextLine()) s.failAtEnd("expected '" + std::string(word) + "' " + std::string(context));
    const std::string_view t = s.token();
    if (t != word) {
      s.fail("expected '" + std::string(word) + "' " + std::string(context) + ", found " +
             describeToken(t));
    }
  };
  bool any = false;
  while (s.nextLine()) {
    std::string_view t = s.token();
    if (t != "solid") s.fail("expected 'solid', found " + describeToken(t));
    any = true;
    long facet = 0;
    for (;;) {
      if (!s.nextLine()) s.failAtEnd("expected 'facet' or 'endsolid'");
      t = s.token();
      if (t == "endsolid") break;
      if (t != "facet") s.fail("expected 'facet' or 'endsolid', found " + describeToken(t));
      if (s.token() != "normal") s.fail("expected 'facet normal nx ny nz'");
      for (int i = 0; i < 3; ++i) s.number("a normal component");
      s.expectLineEnd("the facet normal");
      expect("outer", "(outer loop) in facet " + std::to_string(facet));
      if (s.token() != "loop") s.fail("expected 'outer loop'");
      core::Vec3 v[3];
      for (int k = 0; k < 3; ++k) {
        expect("vertex",
               "(corner " + std::to_string(k + 1) + " of facet " + std::to_string(facet) + ")");
        for (int i = 0; i < 3; ++i) v[k][i] = s.number("a vertex coordinate");
        s.expectLineEnd("the vertex coordinates");
      }
      expect("endloop", "after the 3 vertices of facet " + std::to_string(facet));
      expect("endfacet", "after 'endloop' of facet " + std::to_string(facet));
      addTriangle(mesh, v);
      ++facet;
    }
  }
  if (!any) s.failAtEnd("the file is empty, expected 'solid'");
}

}  // namespace

core::SurfaceMesh readStl(const std::filesystem::path& path) {
  const std::string data = readFileBytes(path);
  const std::string file = path.string();
  core::SurfaceMesh mesh;
  const bool startsWithSolid = data.compare(0, 5, "solid") == 0;
  bool binary = false;
  if (data.size() >= 84) {
    const std::uint64_t count = loadScalar<std::uint32_t>(data.data() + 80, Endian::Little);
    binary = data.size() == 84 + 50 * count;
    if (!binary && !startsWithSolid) {
      throw core::Error("file '" + file + "': binary STL header says " + std::to_string(count) +
                        " triangles (" + std::to_string(84 + 50 * count) +
                        " bytes) but the file has " + std::to_string(data.size()) +
                        " bytes (truncated or not an STL file)");
    }
  } else if (!startsWithSolid) {
    throw core::Error("file '" + file + "': too short for a binary STL file (" +
                      std::to_string(data.size()) + " bytes) and not ASCII STL");
  }
  if (binary) {
    readBinary(data, file, mesh);
  } else {
    readAscii(data, file, mesh);
  }
  core::weldCoincidentVertices(mesh);
  if (mesh.triangles.empty()) {
    throw core::Error("file '" + file + "': the mesh has no (non-degenerate) triangles");
  }
  return mesh;
}

}  // namespace tfd::io
