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

}  // namespace

core::SurfaceMesh readPly(const std::filesystem::path& path) {
  const std::string data = readFileBytes(path);
  const std::string file = path.string();
  TextScanner h(data, file, 0);

  // Header.
  if (!h.nextLine() || h.token() != "ply") {
    throw core::Error("file '" + file + "': not a PLY file (the first line must be 'ply')");
  }
  h.expectLineEnd("'ply'");
  if (!h.nextLine()) h.failAtEnd("expected the 'format' line");
  if (h.token() != "format") h.fail("expected the 'format' line after 'ply'");
  const std::string_view format = h.token();
  bool ascii = false;
  Endian endian = Endian::Little;
  if (format == "ascii") {
    ascii = true;
  } else if (format == "binary_big_endian") {
    endian = Endian::Big;
  } else if (format != "binary_little_endian") {
    h.fail("unknown PLY format " + describeToken(format) +
           "; expected ascii, binary_little_endian or binary_big_endian");
  }
  if (h.token() != "1.0") h.fail("expected PLY version 1.0");
  std::vector<Element> elements;
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
      p.name = printableText(h.token());
      if (p.name.empty()) h.fail("expected a property name");
      h.expectLineEnd("the property name");
      elements.back().properties.push_back(std::move(p));
    } else if (keyword == "end_header") {
      ended = true;
    } else {
      h.fail("unexpected " + describeToken(keyword) + " in the PLY header");
    }
  }
  if (!ended) h.failAtEnd("the header has no 'end_header'");

  // Which properties hold the geometry.
  int vertexElement = -1, faceElement = -1, xyz[3] = {-1, -1, -1}, indices = -1;
  for (int e = 0; e < int(elements.size()); ++e) {
    const auto& el = elements[e];
    if (el.name == "vertex") {
      vertexElement = e;
      for (int p = 0; p < int(el.properties.size()); ++p) {
        const auto& prop = el.properties[p];
        for (int c = 0; c < 3; ++c) {
          if (prop.name == std::string(1, char('x' + c)) && !prop.list) xyz[c] = p;
        }
      }
    } else if (el.name == "face") {
      faceElement = e;
      for (int p = 0; p < int(el.properties.size()); ++p) {
        const auto& prop = el.properties[p];
        if ((prop.name == "vertex_indices" || prop.name == "vertex_index") && prop.list) {
          if (!isInteger(prop.type)) {
            throw core::Error("file '" + file + "': face property '" + prop.name +
                              "' must have an integer type");
          }
          indices = p;
        }
      }
    }
  }
  if (vertexElement < 0 || xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) {
    throw core::Error("file '" + file +
                      "': the header declares no 'vertex' element with properties x, y, z");
  }
  if (faceElement < 0 || indices < 0) {
    throw core::Error("file '" + file +
                      "': the header declares no 'face' element with a 'vertex_indices' list");
  }

  core::SurfaceMesh mesh;
  const long long nv = elements[vertexElement].count;
  if (nv > (long long)data.size()) {
    throw core::Error("file '" + file + "': " + std::to_string(nv) +
                      " vertices cannot fit in the file");
  }
  mesh.positions.reserve(nv);
  std::vector<long long> corners;
  auto addFace = [&](long long f, const auto& failHere) {
    if (corners.size() < 3) {
      failHere("face " + std::to_string(f) + " has " + std::to_string(corners.size()) +
               " vertices; a face needs at least 3");
    }
    for (long long c : corners) {
      if (c < 0 || c >= nv) {
        failHere("face " + std::to_string(f) + " uses vertex " + std::to_string(c) +
                 ", out of range [0, " + std::to_string(nv) + ")");
      }
    }
    for (std::size_t i = 2; i < corners.size(); ++i) {
      mesh.triangles.push_back({int(corners[0]), int(corners[i - 1]), int(corners[i])});
    }
  };

  if (ascii) {
    TextScanner s(data, file, 0, h.nextOffset(), h.lineNumber() + 1);
    for (int e = 0; e < int(elements.size()); ++e) {
      const Element& el = elements[e];
      for (long long i = 0; i < el.count; ++i) {
        if (!s.nextLine()) {
          s.failAtEnd("expected " + std::to_string(el.count) + " " + el.name + " lines, found " +
                      std::to_string(i));
        }
        core::Vec3 p = core::Vec3::Zero();
        corners.clear();
        for (int q = 0; q < int(el.properties.size()); ++q) {
          const Property& prop = el.properties[q];
          const std::string what =
              "property '" + prop.name + "' of " + el.name + " " + std::to_string(i);
          if (prop.list) {
            const long long n = s.integer("the list length of " + what);
            if (n < 0) s.fail("negative list length in " + what);
            for (long long k = 0; k < n; ++k) {
              if (e == faceElement && q == indices) {
                corners.push_back(s.integer("a vertex index in " + what));
              } else {
                s.number("a value of " + what);
              }
            }
          } else {
            const double value = s.number(what);
            if (e == vertexElement) {
              for (int c = 0; c < 3; ++c) {
                if (q == xyz[c]) p[c] = value;
              }
            }
          }
        }
        s.expectLineEnd(el.name + " " + std::to_string(i));
        if (e == vertexElement) mesh.positions.push_back(p);
        if (e == faceElement) addFace(i, [&](const std::string& m) { s.fail(m); });
      }
    }
    if (s.nextLine()) s.fail("unexpected " + describeToken(s.token()) + " after the last element");
  } else {
    BinaryCursor c{data, h.nextOffset(), endian};
    for (int e = 0; e < int(elements.size()); ++e) {
      const Element& el = elements[e];
      for (long long i = 0; i < el.count; ++i) {
        auto truncated = [&]() {
          throw core::Error("file '" + file + "': expected " + std::to_string(el.count) + " " +
                            el.name + " records, found " + std::to_string(i) +
                            " (file ended at byte " + std::to_string(data.size()) + ")");
        };
        core::Vec3 p = core::Vec3::Zero();
        corners.clear();
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
              if (e == faceElement && q == indices) corners.push_back((long long)v);
            }
          } else {
            if (!c.has(sizeOf(prop.type))) truncated();
            const double v = c.read(prop.type);
            if (e == vertexElement) {
              for (int k = 0; k < 3; ++k) {
                if (q == xyz[k]) p[k] = v;
              }
            }
          }
        }
        if (e == vertexElement) {
          if (!p.allFinite()) {
            throw core::Error("file '" + file + "': vertex " + std::to_string(i) +
                              " has a non-finite coordinate");
          }
          mesh.positions.push_back(p);
        }
        if (e == faceElement) {
          addFace(i, [&](const std::string& m) { throw core::Error("file '" + file + "': " + m); });
        }
      }
    }
    if (c.pos != data.size()) {
      throw core::Error("file '" + file + "': " + std::to_string(data.size() - c.pos) +
                        " unexpected bytes after the last element");
    }
  }
  if (mesh.triangles.empty()) {
    throw core::Error("file '" + file + "': the mesh has no faces");
  }
  return mesh;
}

}  // namespace tfd::io
