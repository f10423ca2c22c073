// TetGen .node/.ele reader (io/tetgen/node_ele.h).
#include <string>
#include <vector>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/tet_mesh_build.h"
#include "io/tetgen/node_ele.h"
#include "io/text_format.h"
#include "io/text_scanner.h"

namespace tfd::io {

namespace fs = std::filesystem;

std::shared_ptr<const core::TetMesh> readTetgen(const fs::path& path) {
  const fs::path base = detail::tetgenBase(path);
  const fs::path nodePath = detail::withExtension(base, ".node"),
                 elePath = detail::withExtension(base, ".ele");

  // .node: <#points> <dimension 3> <#attributes> <#boundary markers 0|1>, then
  // <index> <x> <y> <z> [attributes] [marker].
  const std::string nodeText = readFileBytes(nodePath);
  TextScanner n(nodeText, nodePath.string());
  if (!n.nextLine()) n.failAtEnd("the file is empty, expected '<points> 3 <attributes> <markers>'");
  const long long count = n.integer("the number of points");
  if (count < 0 || count > (long long)nodeText.size()) n.fail("implausible number of points");
  if (!n.atLineEnd()) {
    const long long dim = n.integer("the dimension");
    if (dim != 3) n.fail("the dimension must be 3, found " + std::to_string(dim));
  }
  long long attributes = 0, markers = 0;
  if (!n.atLineEnd()) attributes = n.integer("the number of point attributes");
  if (!n.atLineEnd()) markers = n.integer("the number of boundary markers");
  if (attributes < 0 || markers < 0 || markers > 1) n.fail("bad attribute or marker count");
  n.expectLineEnd("the .node header");
  std::vector<core::Vec3> positions;
  positions.reserve(count);
  long long first = 0;
  for (long long i = 0; i < count; ++i) {
    if (!n.nextLine()) {
      n.failAtEnd("expected " + std::to_string(count) + " points, found " + std::to_string(i));
    }
    const long long index = n.integer("a point number");
    if (i == 0) {
      if (index != 0 && index != 1) n.fail("the first point number must be 0 or 1");
      first = index;
    } else if (index != first + i) {
      n.fail("expected point number " + std::to_string(first + i) + ", found " +
             std::to_string(index) + " (points must be numbered consecutively)");
    }
    core::Vec3 p;
    for (int k = 0; k < 3; ++k) {
      p[k] = n.number(std::string("coordinate ") + char('x' + k) + " of point " +
                      std::to_string(index));
    }
    for (long long a = 0; a < attributes + markers; ++a) n.number("a point attribute or marker");
    n.expectLineEnd("point " + std::to_string(index));
    positions.push_back(p);
  }
  if (n.nextLine()) n.fail("unexpected " + describeToken(n.token()) + " after the last point");

  // .ele: <#tets> <nodes per tet 4|10> <#attributes>, then <index> <n1> ... [attributes].
  const std::string eleText = readFileBytes(elePath);
  TextScanner e(eleText, elePath.string());
  if (!e.nextLine())
    e.failAtEnd("the file is empty, expected '<tets> <nodes per tet> <attributes>'");
  const long long tetCount = e.integer("the number of tets");
  if (tetCount < 0 || tetCount > (long long)eleText.size()) e.fail("implausible number of tets");
  long long corners = 4, tetAttributes = 0;
  if (!e.atLineEnd()) corners = e.integer("the number of nodes per tet");
  if (corners != 4 && corners != 10) {
    e.fail("nodes per tet must be 4 or 10, found " + std::to_string(corners));
  }
  if (!e.atLineEnd()) tetAttributes = e.integer("the number of tet attributes");
  e.expectLineEnd("the .ele header");
  std::vector<core::TetMesh::Tet> tets;
  tets.reserve(tetCount);
  for (long long t = 0; t < tetCount; ++t) {
    if (!e.nextLine()) {
      e.failAtEnd("expected " + std::to_string(tetCount) + " tets, found " + std::to_string(t));
    }
    e.integer("a tet number");
    core::TetMesh::Tet tet;
    for (long long k = 0; k < corners; ++k) {
      const long long v = e.integer("a node of tet " + std::to_string(t));
      if (v < first || v >= first + count) {
        e.fail("tet " + std::to_string(t) + " uses point " + std::to_string(v) +
               ", out of range [" + std::to_string(first) + ", " + std::to_string(first + count) +
               ")");
      }
      if (k < 4) tet[k] = int(v - first);
    }
    for (long long a = 0; a < tetAttributes; ++a) e.number("a tet attribute");
    e.expectLineEnd("tet " + std::to_string(t));
    tets.push_back(tet);
  }
  if (e.nextLine()) e.fail("unexpected " + describeToken(e.token()) + " after the last tet");
  return buildTetMesh(std::move(positions), std::move(tets), "file '" + elePath.string() + "'");
}

}  // namespace tfd::io
