// PLY reader, ASCII and binary (see io/mesh/surface_readers.h).
#include <string>
#include <vector>

#include "core/error.h"
#include "io/binary_io.h"
#include "io/mesh/surface_readers.h"
#include "io/text_scanner.h"

namespace tfd::io {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parseType(std::string_view name, Type& type) {
  static const std::pair<std::string_view, Type> kNames[] = {
      {"char", Type::Int8},      {"int8", Type::Int8},       {"uchar", Type::UInt8},
      {"uint8", Type::UInt8},    {"short", Type::Int16},     {"int16", Type::Int16},
      {"ushort", Type::UInt16},  {"uint16", Type::UInt16},   {"int", Type::Int32},
      {"int32", Type::Int32},    {"uint", Type::UInt32},     {"uint32", Type::UInt32},
      {"float", Type::Float32},  {"float32", Type::Float32}, {"double", Type::Float64},
      {"float64", Type::Float64}};
  for (const auto& [n, t] : kNames) {
    if (n == name) {
      type = t;
      return true;
    }
  }
  return false;
}

int sizeOf(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
  }
  return 0;
}

bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool list = false;
  Type countType = Type::UInt8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

/// Binary cursor over the body, with truncation reported by the caller.
struct BinaryCursor {
  const std::string& data;
  std::size_t pos;
  Endian endian;

  bool has(std::size_t bytes) const { return pos + bytes <= data.size(); }
  double read(Type t) {
    const char* p = data.data() + pos;
    pos += sizeOf(t);
    switch (t) {
      case Type::Int8:
        return double(static_cast<signed char>(*p));
      case Type::UInt8:
        return double(static_cast<unsigned char>(*p));
      case Type::Int16:
        return loadScalar<std::int16_t>(p, endian);
      case Type::UInt16:
        return loadScalar<std::uint16_t>(p, endian);
      case Type::Int32:
        return loadScalar<std::int32_t>(p, endian);
      case Type::UInt32:
        return loadScalar<std::uint32_t>(p, endian);
      case Type::Float32:
        return loadScalar<float>(p, endian);
      case Type::Float64:
        return loadScalar<double>(p, endian);
    }
    return 0;
  }
};

struct Header {
  bool ascii = false;
  Endian endian = Endian::Little;
  std::vector<Element> elements;
};

/// One 'property' line (after the keyword) of the last element.
Property parseProperty(TextScanner& h) {
  Property p;
  std::string_view typeName = h.token();
  if (typeName == "list") {
    p.list = true;
    const std::string_view countName = h.token();
    if (!parseType(countName, p.countType) || !isInteger(p.countType)) {
      h.fail("expected an integer type for the list count, found " + describeToken(countName));
    }
    typeName = h.token();
  }
  if (!parseType(typeName, p.type)) {
    h.fail("unknown property type " + describeToken(typeName));
  }
  p.name = printableText(h.token());  // names reach messages
  if (p.name.empty()) h.fail("expected a property name");
  h.expectLineEnd("the property name");
  return p;
}

/// The header from 'ply' to 'end_header'; `h` is left on the 'end_header' line.
Header parseHeader(TextScanner& h, const std::string& file) {
  if (!h.nextLine() || h.token() != "ply") {
    throw core::Error("file '" + file + "': not a PLY file (the first line must be 'ply')");
  }
  h.expectLineEnd("'ply'");
  if (!h.nextLine()) h.failAtEnd("expected the 'format' line");
  if (h.token() != "format") h.fail("expected the 'format' line after 'ply'");
  const std::string_view format = h.token();
  Header header;
  if (format == "ascii") {
    header.ascii = true;
  } else if (format == "binary_big_endian") {
    header.endian = Endian::Big;
  } else if (format != "binary_little_endian") {
    h.fail("unknown PLY format " + describeToken(format) +
           "; expected ascii, binary_little_endian or binary_big_endian");
  }
  if (h.token() != "1.0") h.fail("expected PLY version 1.0");
  std::vector<Element>& elements = header.elements;
  bool ended = false;
  while (!ended && h.nextLine()) {
    const std::string_view keyword = h.token();
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "element") {
      Element e;
      e.name = printableText(h.token());  // names reach messages
      if (e.name.empty()) h.fail("expected an element name");
      e.count = h.integer("the count of element '" + e.name + "'");
      if (e.count < 0) h.fail("negative count of element '" + e.name + "'");
      h.expectLineEnd("the element count");
      elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (elements.empty()) h.fail("'property' before any 'element'");
      elements.back().properties.push_back(parseProperty(h));
    } else if (keyword == "end_header") {
      ended = true;
    } else {
      h.fail("unexpected " + describeToken(keyword) + " in the PLY header");
    }
  }
  if (!ended) h.failAtEnd("the header has no 'end_header'");
  return header;
}

/// Which elements and properties hold the geometry.
struct Layout {
  int vertexElement = -1, faceElement = -1;
  int xyz[3] = {-1, -1, -1};
  int indices = -1;
};

Layout locateGeometry(const std::vector<Element>& elements, const std::string& file) {
  Layout g;
  for (int e = 0; e < int(elements.size()); ++e) {
    const auto& el = elements[e];
    if (el.name == "vertex") {
      g.vertexElement = e;
      for (int p = 0; p < int(el.properties.size()); ++p) {
        const auto& prop = el.properties[p];
        for (int c = 0; c < 3; ++c) {
          if (prop.name == std::string(1, char('x' + c)) && !prop.list) g.xyz[c] = p;
        }
      }
    } else if (el.name == "face") {
      g.faceElement = e;
      for (int p = 0; p < int(el.properties.size()); ++p) {
        const auto& prop = el.properties[p];
        if ((prop.name == "vertex_indices" || prop.name == "vertex_index") && prop.list) {
          if (!isInteger(prop.type)) {
            throw core::Error("file '" + file + "': face property '" + prop.name +
                              "' must have an integer type");
          }
          g.indices = p;
        }
      }
    }
  }
  if (g.vertexElement < 0 || g.xyz[0] < 0 || g.xyz[1] < 0 || g.xyz[2] < 0) {
    throw core::Error("file '" + file +
                      "': the header declares no 'vertex' element with properties x, y, z");
  }
  if (g.faceElement < 0 || g.indices < 0) {
    throw core::Error("file '" + file +
                      "': the header declares no 'face' element with a 'vertex_indices' list");
  }
  return g;
}

/// Collects vertices and fan-triangulated faces while the body is read.
struct MeshBuilder {
  const Layout& layout;
  long long vertexCount;
  core::SurfaceMesh mesh;
  core::Vec3 point = core::Vec3::Zero();  ///< the current vertex record
  std::vector<long long> corners;         ///< the current face record

  void startRecord() {
    point = core::Vec3::Zero();
    corners.clear();
  }
  /// A scalar property q of element e.
  void scalar(int e, int q, double value) {
    if (e != layout.vertexElement) return;
    for (int c = 0; c < 3; ++c) {
      if (q == layout.xyz[c]) point[c] = value;
    }
  }
  bool isIndexList(int e, int q) const { return e == layout.faceElement && q == layout.indices; }
  template <class Fail>
  void addFace(long long f, const Fail& failHere) {
    if (corners.size() < 3) {
      failHere("face " + std::to_string(f) + " has " + std::to_string(corners.size()) +
               " vertices; a face needs at least 3");
    }
    for (long long c : corners) {
      if (c < 0 || c >= vertexCount) {
        failHere("face " + std::to_string(f) + " uses vertex " + std::to_string(c) +
                 ", out of range [0, " + std::to_string(vertexCount) + ")");
      }
    }
    for (std::size_t i = 2; i < corners.size(); ++i) {
      mesh.triangles.push_back({int(corners[0]), int(corners[i - 1]), int(corners[i])});
    }
  }
};

void readAsciiBody(const std::string& data, const std::string& file, const TextScanner& h,
                   const std::vector<Element>& elements, MeshBuilder& b) {
  TextScanner s(data, file, 0, h.nextOffset(), h.lineNumber() + 1);
  for (int e = 0; e < int(elements.size()); ++e) {
    const Element& el = elements[e];
    for (long long i = 0; i < el.count; ++i) {
      if (!s.nextLine()) {
        s.failAtEnd("expected " + std::to_string(el.count) + " " + el.name + " lines, found " +
                    std::to_string(i));
      }
      b.startRecord();
      for (int q = 0; q < int(el.properties.size()); ++q) {
        const Property& prop = el.properties[q];
        const std::string what =
            "property '" + prop.name + "' of " + el.name + " " + std::to_string(i);
        if (prop.list) {
          const long long n = s.integer("the list length of " + what);
          if (n < 0) s.fail("negative list length in " + what);
          for (long long k = 0; k < n; ++k) {
            if (b.isIndexList(e, q)) {
              b.corners.push_back(s.integer("a vertex index in " + what));
            } else {
              s.number("a value of " + what);
            }
          }
        } else {
          b.scalar(e, q, s.number(what));
        }
      }
      s.expectLineEnd(el.name + " " + std::to_string(i));
      if (e == b.layout.vertexElement) b.mesh.positions.push_back(b.point);
      if (e == b.layout.faceElement) b.addFace(i, [&](const std::string& m) { s.fail(m); });
    }
  }
  if (s.nextLine()) s.fail("unexpected " + describeToken(s.token()) + " after the last element");
}

void readBinaryBody(const std::string& data, const std::string& file, std::size_t offset,
                    Endian endian, const std::vector<Element>& elements, MeshBuilder& b) {
  BinaryCursor c{data, offset, endian};
  for (int e = 0; e < int(elements.size()); ++e) {
    const Element& el = elements[e];
    for (long long i = 0; i < el.count; ++i) {
      auto truncated = [&]() {
        throw core::Error("file '" + file + "': expected " + std::to_string(el.count) + " " +
                          el.name + " records, found " + std::to_string(i) +
                          " (file ended at byte " + std::to_string(data.size()) + ")");
      };
      b.startRecord();
      for (int q = 0; q < int(el.properties.size()); ++q) {
        const Property& prop = el.properties[q];
        if (prop.list) {
          if (!c.has(sizeOf(prop.countType))) truncated();
          const double n = c.read(prop.countType);
          if (n < 0) {
            throw core::Error("file '" + file + "': negative list length in " + el.name + " " +
                              std::to_string(i));
          }
          if (!c.has(std::size_t(n) * sizeOf(prop.type))) truncated();
          for (long long k = 0; k < (long long)n; ++k) {
            const double v = c.read(prop.type);
            if (b.isIndexList(e, q)) b.corners.push_back((long long)v);
          }
        } else {
          if (!c.has(sizeOf(prop.type))) truncated();
          b.scalar(e, q, c.read(prop.type));
        }
      }
      if (e == b.layout.vertexElement) {
        if (!b.point.allFinite()) {
          throw core::Error("file '" + file + "': vertex " + std::to_string(i) +
                            " has a non-finite coordinate");
        }
        b.mesh.positions.push_back(b.point);
      }
      if (e == b.layout.faceElement) {
        b.addFace(i, [&](const std::string& m) { throw core::Error("file '" + file + "': " + m); });
      }
    }
  }
  if (c.pos != data.size()) {
    throw core::Error("file '" + file + "': " + std::to_string(data.size() - c.pos) +
                      " unexpected bytes after the last element");
  }
}

}  // namespace

core::SurfaceMesh readPly(const std::filesystem::path& path) {
  const std::string data = readFileBytes(path);
  const std::string file = path.string();
  TextScanner h(data, file, 0);
  const Header header = parseHeader(h, file);
  const Layout layout = locateGeometry(header.elements, file);

  const long long nv = header.elements[layout.vertexElement].count;
  if (nv > (long long)data.size()) {
    throw core::Error("file '" + file + "': " + std::to_string(nv) +
                      " vertices cannot fit in the file");
  }
  MeshBuilder builder{layout, nv, {}, core::Vec3::Zero(), {}};
  builder.mesh.positions.reserve(nv);
  if (header.ascii) {
    readAsciiBody(data, file, h, header.elements, builder);
  } else {
    readBinaryBody(data, file, h.nextOffset(), header.endian, header.elements, builder);
  }
  if (builder.mesh.triangles.empty()) {
    throw core::Error("file '" + file + "': the mesh has no faces");
  }
  return std::move(builder.mesh);
}

}  // namespace tfd::io
