// Gmsh ASCII .msh writer, formats 2.2 and 4.1 (see io/tet_mesh_io.h).
#include <string>

#include "io/file_bytes.h"
#include "io/mesh/gmsh.h"
#include "io/text_format.h"

namespace tfd::io {

void writeGmsh(const std::filesystem::path& path, const core::TetMesh& mesh, GmshVersion version) {
  const std::size_t n = mesh.vertexCount(), m = mesh.tetCount();
  std::string out = version == GmshVersion::V2 ? "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                               : "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  auto xyz = [&](std::size_t v) {
    for (int k = 0; k < 3; ++k) {
      if (k) out += ' ';
      appendNumber(out, mesh.positions()[v][k]);
    }
  };
  if (version == GmshVersion::V2) {
    out += "$Nodes\n";
    appendNumber(out, n);
    out += '\n';
    for (std::size_t v = 0; v < n; ++v) {
      appendNumber(out, v + 1);
      out += ' ';
      xyz(v);
      out += '\n';
    }
    out += "$EndNodes\n$Elements\n";
    appendNumber(out, m);
    out += '\n';
    for (std::size_t t = 0; t < m; ++t) {
      appendNumber(out, t + 1);
      out += " 4 2 1 1";  // type 4 (tet), tags: physical 1, elementary 1
      for (int v : mesh.tets()[t]) {
        out += ' ';
        appendNumber(out, v + 1);
      }
      out += '\n';
    }
    out += "$EndElements\n";
  } else {
    // One volume entity (tag 1) with its bounding box, no physical groups.
    out += "$Entities\n0 0 0 1\n1";
    for (const core::Vec3* b : {&mesh.boundsMin(), &mesh.boundsMax()}) {
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        appendNumber(out, (*b)[k]);
      }
    }
    out += " 0 0\n$EndEntities\n$Nodes\n1 ";
    appendNumber(out, n);
    out += " 1 ";
    appendNumber(out, n);
    out += "\n3 1 0 ";
    appendNumber(out, n);
    out += '\n';
    for (std::size_t v = 0; v < n; ++v) {
      appendNumber(out, v + 1);
      out += '\n';
    }
    for (std::size_t v = 0; v < n; ++v) {
      xyz(v);
      out += '\n';
    }
    out += "$EndNodes\n$Elements\n1 ";
    appendNumber(out, m);
    out += " 1 ";
    appendNumber(out, m);
    out += "\n3 1 4 ";
    appendNumber(out, m);
    out += '\n';
    for (std::size_t t = 0; t < m; ++t) {
      appendNumber(out, t + 1);
      for (int v : mesh.tets()[t]) {
        out += ' ';
        appendNumber(out, v + 1);
      }
      out += '\n';
    }
    out += "$EndElements\n";
  }
  writeFileBytes(path, out);
}

}  // namespace tfd::io
