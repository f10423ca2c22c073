// Gmsh ASCII .msh reader, formats 2.x and 4.x (see io/tet_mesh_io.h).
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/mesh/gmsh.h"
#include "io/tet_mesh_build.h"
#include "io/text_scanner.h"

namespace tfd::io {
namespace {

enum class Kind { Tet, OtherVolume, Ignored };

/// Gmsh element types: tets of order 1..4 keep their first four (corner) nodes.
Kind kindOf(long long type) {
  switch (type) {
    case 4:
    case 11:
    case 29:
    case 30:
    case 31:
      return Kind::Tet;
    case 5:
    case 6:
    case 7:
    case 12:
    case 13:
    case 14:
    case 17:
    case 18:
    case 19:
    case 92:
    case 93:
      return Kind::OtherVolume;
    default:
      return Kind::Ignored;
  }
}

const char* volumeName(long long type) {
  switch (type) {
    case 5:
    case 12:
    case 17:
    case 92:
    case 93:
      return "hexahedron";
    case 6:
    case 13:
    case 18:
      return "prism";
    default:
      return "pyramid";
  }
}

class GmshReader {
 public:
  GmshReader(const std::string& text, const std::string& file)
      : s_(text, file, 0), size_(static_cast<long long>(text.size())) {}

  std::shared_ptr<const core::TetMesh> read() {
    while (s_.nextLine()) {
      const std::string_view section = s_.token();
      if (section == "$MeshFormat") {
        readFormat();
      } else if (section == "$NOD" || section == "$ELM") {
        s_.fail("Gmsh format 1 is not supported; save the mesh in format 2 or 4 (ASCII)");
      } else if (!section.empty() && section[0] == '$' && section.substr(0, 4) != "$End") {
        if (version_ == 0) s_.fail("expected '$MeshFormat' first, found " + describeToken(section));
        if (section == "$Nodes") {
          version_ >= 4 ? readNodes4() : readNodes2();
          expectEnd("$EndNodes");
        } else if (section == "$Elements") {
          if (!haveNodes_) s_.fail("'$Elements' before '$Nodes'");
          version_ >= 4 ? readElements4() : readElements2();
          expectEnd("$EndElements");
        } else {
          skipSection(std::string(section.substr(1)));
        }
      } else {
        s_.fail("expected a section such as '$MeshFormat', '$Nodes' or '$Elements', found " +
                describeToken(section));
      }
    }
    if (version_ == 0) s_.failAtEnd("not a Gmsh file: no '$MeshFormat' section");
    if (tets_.empty()) {
      throw core::Error("file '" + s_.fileName() + "': no tetrahedra in the mesh" +
                        (skipped_ ? " (only lower-dimensional elements)" : ""));
    }
    return buildTetMesh(std::move(positions_), std::move(tets_), "file '" + s_.fileName() + "'");
  }

 private:
  void readFormat() {
    nextLine("the format line 'version file-type data-size'");
    const double version = s_.number("the format version");
    const long long fileType = s_.integer("the file type (0 ASCII, 1 binary)");
    if (version < 2 || version >= 5) {
      s_.fail("Gmsh format " + std::to_string(version).substr(0, 3) +
              " is not supported; save the mesh in format 2 or 4");
    }
    if (fileType != 0) s_.fail("binary .msh files are not supported; save the mesh as ASCII");
    version_ = version;
    // 4.0 and 4.1 differ in the block headers.
    v40_ = version >= 4 && version < 4.05;
    expectEnd("$EndMeshFormat");
  }

  void nextLine(const std::string& expected) {
    if (!s_.nextLine()) s_.failAtEnd("expected " + expected);
  }

  void expectEnd(const char* end) {
    nextLine(std::string("'") + end + "'");
    const std::string_view t = s_.token();
    if (t != end) s_.fail(std::string("expected '") + end + "', found " + describeToken(t));
  }

  void skipSection(const std::string& name) {
    const std::string end = "$End" + name;
    for (;;) {
      if (!s_.nextLine()) s_.failAtEnd("expected '" + printableText(end) + "'");
      if (s_.token() == end) return;
    }
  }

  /// Reads item i of n of a section; a section end or the file end first is a truncation.
  void itemLine(long long i, long long n, const char* what) {
    const std::string expected =
        "expected " + std::to_string(n) + " " + what + ", found " + std::to_string(i);
    if (!s_.nextLine()) s_.failAtEnd(expected);
    if (s_.line().substr(0, 4) == "$End")
      s_.fail(expected + " before '" + std::string(s_.line()) + "'");
  }

  void addNode(long long tag, const core::Vec3& p) {
    if (!tagToIndex_.emplace(tag, int(positions_.size())).second) {
      s_.fail("node " + std::to_string(tag) + " is defined twice");
    }
    positions_.push_back(p);
  }

  core::Vec3 readXyz(long long tag) {
    core::Vec3 p;
    for (int k = 0; k < 3; ++k) {
      p[k] =
          s_.number(std::string("coordinate ") + char('x' + k) + " of node " + std::to_string(tag));
    }
    return p;
  }

  /// A count read from the file, before anything is reserved for it: each item takes at
  /// least a byte of the file.
  void requirePlausibleCount(long long count, const char* what) {
    if (count < 0 || count > size_)
      s_.fail("the number of " + std::string(what) + " (" + std::to_string(count) +
              ") cannot fit in a file of " + std::to_string(size_) + " bytes");
  }

  /// A block's count, which must fit in what the section header announced and is not yet seen.
  void requireBlockCount(long long count, long long left, const char* what) {
    if (count < 0 || count > left)
      s_.fail("a block announces " + std::to_string(count) + " " + what + ", but the header " +
              "leaves " + std::to_string(left));
  }

  void readNodes2() {
    nextLine("the number of nodes");
    const long long n = s_.integer("the number of nodes");
    requirePlausibleCount(n, "nodes");
    positions_.reserve(n);
    for (long long i = 0; i < n; ++i) {
      itemLine(i, n, "nodes");
      const long long tag = s_.integer("a node tag");
      const core::Vec3 p = readXyz(tag);
      s_.expectLineEnd("node " + std::to_string(tag));
      addNode(tag, p);
    }
    haveNodes_ = true;
  }

  void readNodes4() {
    nextLine("the $Nodes header");
    const long long blocks = s_.integer("the number of entity blocks");
    const long long total = s_.integer("the number of nodes");
    requirePlausibleCount(total, "nodes");
    positions_.reserve(total);
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      itemLine(b, blocks, "node blocks");
      long long parametric, count;
      if (v40_) {  // entityTag entityDim parametric numNodes
        s_.integer("the entity tag");
        s_.integer("the entity dimension");
      } else {  // entityDim entityTag parametric numNodes
        s_.integer("the entity dimension");
        s_.integer("the entity tag");
      }
      parametric = s_.integer("the parametric flag");
      count = s_.integer("the number of nodes in the block");
      requireBlockCount(count, total - seen, "nodes");
      (void)parametric;  // parametric coordinates follow x y z; they are ignored
      if (v40_) {
        for (long long i = 0; i < count; ++i) {
          itemLine(seen + i, total, "nodes");
          const long long tag = s_.integer("a node tag");
          addNode(tag, readXyz(tag));
        }
      } else {
        std::vector<long long> tags(count);
        for (long long i = 0; i < count; ++i) {
          itemLine(seen + i, total, "node tags");
          tags[i] = s_.integer("a node tag");
          s_.expectLineEnd("the node tag");
        }
        for (long long i = 0; i < count; ++i) {
          itemLine(seen + i, total, "node coordinates");
          addNode(tags[i], readXyz(tags[i]));
        }
      }
      seen += count;
    }
    if (seen != total) {
      s_.fail("the $Nodes header announces " + std::to_string(total) +
              " nodes but the blocks hold " + std::to_string(seen));
    }
    haveNodes_ = true;
  }

  int nodeIndex(long long tag, long long element) {
    const auto it = tagToIndex_.find(tag);
    if (it == tagToIndex_.end()) {
      s_.fail("element " + std::to_string(element) + " uses node " + std::to_string(tag) +
              ", which is not defined");
    }
    return it->second;
  }

  /// Reads the nodes of element `tag` of `type` from the rest of the line.
  void element(long long tag, long long type) {
    const Kind kind = kindOf(type);
    if (kind == Kind::OtherVolume) {
      s_.fail("element " + std::to_string(tag) + " is a " + volumeName(type) + " (type " +
              std::to_string(type) + "); only tetrahedra are supported");
    }
    if (kind == Kind::Ignored) {
      ++skipped_;
      return;
    }
    core::TetMesh::Tet tet;
    for (int k = 0; k < 4; ++k) {
      tet[k] = nodeIndex(s_.integer("a node of element " + std::to_string(tag)), tag);
    }
    tets_.push_back(tet);
  }

  void readElements2() {
    nextLine("the number of elements");
    const long long n = s_.integer("the number of elements");
    for (long long i = 0; i < n; ++i) {
      itemLine(i, n, "elements");
      const long long tag = s_.integer("an element number");
      const long long type = s_.integer("the element type");
      const long long tags = s_.integer("the number of tags");
      for (long long k = 0; k < tags; ++k) s_.integer("an element tag");
      element(tag, type);
    }
  }

  void readElements4() {
    nextLine("the $Elements header");
    const long long blocks = s_.integer("the number of entity blocks");
    const long long total = s_.integer("the number of elements");
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      itemLine(b, blocks, "element blocks");
      if (v40_) {  // entityTag entityDim elementType numElements
        s_.integer("the entity tag");
        s_.integer("the entity dimension");
      } else {  // entityDim entityTag elementType numElements
        s_.integer("the entity dimension");
        s_.integer("the entity tag");
      }
      const long long type = s_.integer("the element type");
      const long long count = s_.integer("the number of elements in the block");
      requireBlockCount(count, total - seen, "elements");
      for (long long i = 0; i < count; ++i) {
        itemLine(seen + i, total, "elements");
        element(s_.integer("an element tag"), type);
      }
      seen += count;
    }
  }

  TextScanner s_;
  long long size_;  // bytes of the file
  double version_ = 0;
  bool v40_ = false;
  bool haveNodes_ = false;
  long long skipped_ = 0;
  std::vector<core::Vec3> positions_;
  std::unordered_map<long long, int> tagToIndex_;
  std::vector<core::TetMesh::Tet> tets_;
};

}  // namespace

std::shared_ptr<const core::TetMesh> readGmsh(const std::filesystem::path& path) {
  const std::string text = readFileBytes(path);
  return GmshReader(text, path.string()).read();
}

}  // namespace tfd::io
