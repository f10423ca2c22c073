// VTK XML UnstructuredGrid (.vtu) reader of the tet mesh geometry (see io/tet_mesh_io.h).
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/memory_budget.h"
#include "io/base64.h"
#include "io/binary_io.h"
#include "io/file_bytes.h"
#include "io/tet_mesh_build.h"
#include "io/text_scanner.h"
#include "io/vtk/vtu_reader.h"
#include "io/vtk/xml_lite.h"

namespace tfd::io {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

struct TypeInfo {
  const char* name;
  Type type;
  int size;
};
constexpr TypeInfo kTypes[] = {{"Int8", Type::Int8, 1},       {"UInt8", Type::UInt8, 1},
                               {"Int16", Type::Int16, 2},     {"UInt16", Type::UInt16, 2},
                               {"Int32", Type::Int32, 4},     {"UInt32", Type::UInt32, 4},
                               {"Int64", Type::Int64, 8},     {"UInt64", Type::UInt64, 8},
                               {"Float32", Type::Float32, 4}, {"Float64", Type::Float64, 8}};

enum class CellKind { Tet, OtherVolume, Ignored };

/// VTK cell types: linear, quadratic, Lagrange and Bézier tets keep their four corners.
CellKind cellKind(long long type) {
  switch (type) {
    case 10:
    case 24:
    case 71:
    case 78:
      return CellKind::Tet;
    case 11:
    case 12:
    case 13:
    case 14:
    case 15:
    case 16:
    case 25:
    case 26:
    case 27:
    case 29:
    case 31:
    case 32:
    case 33:
    case 42:
    case 72:
    case 73:
    case 74:
    case 79:
    case 80:
    case 81:
      return CellKind::OtherVolume;
    default:
      return CellKind::Ignored;
  }
}

class VtuReader {
 public:
  VtuReader(const std::string& data, const std::string& file) : data_(data), file_(file) {}

  std::shared_ptr<const core::TetMesh> read() {
    doc_ = parseXml(data_, file_);
    const XmlElement& root = doc_.root;
    if (root.name != "VTKFile")
      fail(root, "the root element is <" + root.name + ">, not <VTKFile>");
    const std::string* type = root.attribute("type");
    if (!type || *type != "UnstructuredGrid") {
      fail(root, "expected a VTKFile of type \"UnstructuredGrid\", found \"" +
                     (type ? *type : std::string()) + "\"");
    }
    if (const std::string* order = root.attribute("byte_order")) {
      if (*order == "BigEndian") {
        endian_ = Endian::Big;
      } else if (*order != "LittleEndian") {
        fail(root, "unknown byte_order \"" + *order + "\"");
      }
    }
    if (const std::string* header = root.attribute("header_type")) {
      if (*header == "UInt64") {
        header64_ = true;
      } else if (*header != "UInt32") {
        fail(root, "unknown header_type \"" + *header + "\"");
      }
    }
    if (const std::string* compressor = root.attribute("compressor")) {
      if (*compressor == "vtkZLibDataCompressor") {
        zlib_ = true;
      } else if (!compressor->empty()) {
        fail(root, "compressor \"" + *compressor +
                       "\" is not supported (only vtkZLibDataCompressor); save uncompressed");
      }
    }
    if (doc_.appendedStart != std::string::npos) {
      const std::string* enc = doc_.appended.attribute("encoding");
      appendedBase64_ = enc && *enc == "base64";
      if (enc && *enc != "base64" && *enc != "raw") {
        fail(doc_.appended, "unknown AppendedData encoding \"" + *enc + "\"");
      }
    }
    const XmlElement* grid = root.child("UnstructuredGrid");
    if (!grid) fail(root, "no <UnstructuredGrid> element");
    const auto pieces = grid->childrenNamed("Piece");
    if (pieces.empty()) fail(*grid, "no <Piece> element");
    for (const XmlElement* piece : pieces) readPiece(*piece);
    if (tets_.empty()) {
      throw core::Error("file '" + file_ + "': no tetrahedra (VTK_TETRA = 10 cells) in the mesh");
    }
    return buildTetMesh(std::move(positions_), std::move(tets_), "file '" + file_ + "'");
  }

 private:
  [[noreturn]] void fail(const XmlElement& e, const std::string& message) const {
    throw core::Error("file '" + file_ + "', line " + std::to_string(e.line) + ": " +
                      printableText(message));
  }

  long long countAttribute(const XmlElement& e, const char* key) const {
    const std::string* v = e.attribute(key);
    long long n;
    if (!v || !parseInteger(*v, n) || n < 0) {
      fail(e, std::string("<") + e.name + "> needs a non-negative integer attribute " + key);
    }
    return n;
  }

  const XmlElement& namedArray(const XmlElement& parent, const char* name) const {
    for (const XmlElement* a : parent.childrenNamed("DataArray")) {
      const std::string* n = a->attribute("Name");
      if (n && *n == name) return *a;
    }
    fail(parent, std::string("<") + parent.name + "> has no DataArray named \"" + name + "\"");
  }

  void readPiece(const XmlElement& piece) {
    const long long nPoints = countAttribute(piece, "NumberOfPoints");
    const long long nCells = countAttribute(piece, "NumberOfCells");
    const XmlElement* points = piece.child("Points");
    if (!points) fail(piece, "the piece has no <Points>");
    const XmlElement* pointArray = points->child("DataArray");
    if (!pointArray) fail(*points, "<Points> has no DataArray");
    const std::vector<double> xyz = values(*pointArray, nPoints, 3);
    const XmlElement* cells = piece.child("Cells");
    if (!cells) fail(piece, "the piece has no <Cells>");
    const std::vector<double> connectivity = values(namedArray(*cells, "connectivity"), -1, 1);
    const std::vector<double> offsets = values(namedArray(*cells, "offsets"), nCells, 1);
    const std::vector<double> types = values(namedArray(*cells, "types"), nCells, 1);

    const int base = int(positions_.size());
    for (long long p = 0; p < nPoints; ++p) {
      positions_.emplace_back(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
    }
    long long start = 0;
    for (long long c = 0; c < nCells; ++c) {
      const long long end = (long long)offsets[c];
      if (end < start || end > (long long)connectivity.size()) {
        fail(*cells, "cell " + std::to_string(c) + " has offset " + std::to_string(end) +
                         ", outside [" + std::to_string(start) + ", " +
                         std::to_string(connectivity.size()) + "]");
      }
      const long long type = (long long)types[c];
      const CellKind kind = cellKind(type);
      if (kind == CellKind::OtherVolume) {
        fail(*cells, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
                         " (not a tetrahedron); only tetrahedra (type 10) are supported");
      }
      if (kind == CellKind::Tet) {
        if (end - start < 4) {
          fail(*cells, "tetrahedron " + std::to_string(c) + " has " + std::to_string(end - start) +
                           " points");
        }
        core::TetMesh::Tet tet;
        for (int k = 0; k < 4; ++k) {
          const long long v = (long long)connectivity[start + k];
          if (v < 0 || v >= nPoints) {
            fail(*cells, "cell " + std::to_string(c) + " uses point " + std::to_string(v) +
                             ", out of range [0, " + std::to_string(nPoints) + ")");
          }
          tet[k] = base + int(v);
        }
        tets_.push_back(tet);
      }
      start = end;
    }
  }

  /// The values of a DataArray as doubles; checks the tuple count when `tuples` >= 0.
  std::vector<double> values(const XmlElement& a, long long tuples, int components) const {
    const std::string* typeName = a.attribute("type");
    const TypeInfo* info = nullptr;
    for (const auto& t : kTypes) {
      if (typeName && *typeName == t.name) info = &t;
    }
    if (!info) fail(a, "DataArray has unknown type \"" + (typeName ? *typeName : "") + "\"");
    if (const std::string* nc = a.attribute("NumberOfComponents")) {
      long long n;
      if (!parseInteger(*nc, n) || n != components) {
        fail(a, "DataArray has NumberOfComponents=\"" + *nc + "\", expected " +
                    std::to_string(components));
      }
    } else if (components != 1) {
      fail(a, "DataArray needs NumberOfComponents=\"" + std::to_string(components) + "\"");
    }
    const std::string* format = a.attribute("format");
    const std::string f = format ? *format : "ascii";
    std::vector<double> out;
    if (f == "ascii") {
      TextScanner s(a.text, file_, 0, 0, a.line);
      while (s.nextLine()) {
        while (!s.atLineEnd()) out.push_back(s.number("a DataArray value"));
      }
    } else if (f == "binary") {
      Base64Decoder decoder(a.text);
      out = decodeBinary(a, *info, decoder, a.text, 0, false);
    } else if (f == "appended") {
      if (doc_.appendedStart == std::string::npos)
        fail(a, "format=\"appended\" but no <AppendedData>");
      long long offset;
      const std::string* o = a.attribute("offset");
      if (!o || !parseInteger(*o, offset) || offset < 0)
        fail(a, "appended DataArray needs an offset");
      const std::size_t at = doc_.appendedStart + std::size_t(offset);
      if (at > data_.size()) fail(a, "appended offset " + *o + " lies past the end of the file");
      if (appendedBase64_) {
        Base64Decoder decoder(data_, at);
        out = decodeBinary(a, *info, decoder, data_, at, false);
      } else {
        Base64Decoder unused(std::string_view{});
        out = decodeBinary(a, *info, unused, data_, at, true);
      }
    } else {
      fail(a, "unknown DataArray format \"" + f + "\"");
    }
    if (tuples >= 0 && (long long)out.size() != tuples * components) {
      fail(a, "DataArray holds " + std::to_string(out.size()) + " values, expected " +
                  std::to_string(tuples * components));
    }
    if (tuples < 0 && out.size() % components != 0)
      fail(a, "DataArray size is not a multiple of its components");
    for (double v : out) {
      if (!std::isfinite(v)) fail(a, "DataArray holds a non-finite value");
    }
    return out;
  }

  /// Reads `bytes` bytes either raw from `source` at `pos` or through the base64 decoder.
  std::string take(const XmlElement& a, Base64Decoder& decoder, std::string_view source,
                   std::size_t& pos, bool raw, std::size_t bytes) const {
    std::string out;
    if (raw) {
      if (pos + bytes > source.size()) {
        fail(a, "binary data ends early: needs " + std::to_string(bytes) + " bytes at offset " +
                    std::to_string(pos) + ", the file has " + std::to_string(source.size()));
      }
      out.assign(source.substr(pos, bytes));
      pos += bytes;
    } else if (!decoder.decode(out, bytes)) {
      fail(a, "bad base64 data: " + decoder.error());
    }
    return out;
  }

  std::uint64_t headerValue(const std::string& bytes, std::size_t i) const {
    return header64_ ? loadScalar<std::uint64_t>(bytes.data() + 8 * i, endian_)
                     : loadScalar<std::uint32_t>(bytes.data() + 4 * i, endian_);
  }

  std::vector<double> decodeBinary(const XmlElement& a, const TypeInfo& info,
                                   Base64Decoder& decoder, std::string_view source, std::size_t pos,
                                   bool raw) const {
    const std::size_t h = header64_ ? 8 : 4;
    std::string bytes;
    if (!zlib_) {
      const std::uint64_t size = headerValue(take(a, decoder, source, pos, raw, h), 0);
      if (size > data_.size() * 4 + 64)
        fail(a, "implausible binary block size " + std::to_string(size));
      bytes = take(a, decoder, source, pos, raw, size);
    } else {
      // Header: block count, uncompressed block size, size of the last block, then the
      // compressed size of each block.
      const std::string head = take(a, decoder, source, pos, raw, 3 * h);
      const std::uint64_t blocks = headerValue(head, 0), blockSize = headerValue(head, 1),
                          lastSize = headerValue(head, 2);
      if (blocks > data_.size()) fail(a, "implausible compressed block count");
      const std::string sizes = take(a, decoder, source, pos, raw, blocks * h);
      for (std::uint64_t b = 0; b < blocks; ++b) {
        const std::uint64_t compressed = headerValue(sizes, b);
        const std::uint64_t expected = (b + 1 == blocks && lastSize != 0) ? lastSize : blockSize;
        if (compressed > data_.size() || expected > (std::uint64_t(1) << 34)) {
          fail(a, "implausible compressed block size");
        }
        // zlib expands at most about 1032:1: a larger announced size is damage, refused before
        // anything is allocated for it.
        if (expected > compressed * 1032 + 64) {
          fail(a, "compressed block " + std::to_string(b) + " announces " +
                      std::to_string(expected) + " bytes from " + std::to_string(compressed) +
                      ", more than zlib can expand");
        }
        core::checkMemory(double(bytes.size()) + double(expected),
                          "file '" + file_ + "', line " + std::to_string(a.line) +
                              ": a compressed DataArray (as the file announces)");
        const std::string in = take(a, decoder, source, pos, raw, compressed);
        std::string block(expected, '\0');
        uLongf length = uLongf(expected);
        const int rc = uncompress(reinterpret_cast<Bytef*>(block.data()), &length,
                                  reinterpret_cast<const Bytef*>(in.data()), uLong(in.size()));
        if (rc != Z_OK || length != expected) {
          fail(a, "zlib could not decompress block " + std::to_string(b) + " (code " +
                      std::to_string(rc) + ")");
        }
        bytes += block;
      }
    }
    if (bytes.size() % info.size != 0) {
      fail(a, "binary block of " + std::to_string(bytes.size()) +
                  " bytes is not a whole number of " + info.name + " values");
    }
    std::vector<double> out(bytes.size() / info.size);
    const char* p = bytes.data();
    for (std::size_t i = 0; i < out.size(); ++i, p += info.size) {
      switch (info.type) {
        case Type::Int8:
          out[i] = double(static_cast<signed char>(*p));
          break;
        case Type::UInt8:
          out[i] = double(static_cast<unsigned char>(*p));
          break;
        case Type::Int16:
          out[i] = loadScalar<std::int16_t>(p, endian_);
          break;
        case Type::UInt16:
          out[i] = loadScalar<std::uint16_t>(p, endian_);
          break;
        case Type::Int32:
          out[i] = loadScalar<std::int32_t>(p, endian_);
          break;
        case Type::UInt32:
          out[i] = loadScalar<std::uint32_t>(p, endian_);
          break;
        case Type::Int64:
          out[i] = double(loadScalar<std::int64_t>(p, endian_));
          break;
        case Type::UInt64:
          out[i] = double(loadScalar<std::uint64_t>(p, endian_));
          break;
        case Type::Float32:
          out[i] = loadScalar<float>(p, endian_);
          break;
        case Type::Float64:
          out[i] = loadScalar<double>(p, endian_);
          break;
      }
    }
    return out;
  }

  const std::string& data_;
  std::string file_;
  XmlDocument doc_;
  Endian endian_ = Endian::Little;
  bool header64_ = false;
  bool zlib_ = false;
  bool appendedBase64_ = false;
  std::vector<core::Vec3> positions_;
  std::vector<core::TetMesh::Tet> tets_;
};

}  // namespace

std::shared_ptr<const core::TetMesh> readVtu(const std::filesystem::path& path) {
  const std::string data = readFileBytes(path);
  return VtuReader(data, path.string()).read();
}

}  // namespace tfd::io
