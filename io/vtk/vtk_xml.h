#pragma once
// A small writer for VTK's XML file formats (.vtu, .vtp): nested elements and DataArrays in
// one of three encodings. It builds the document in memory; save() writes it to one file.
//
// Binary layout (VTK's, with header_type="UInt64" and no compression): each array is a
// little-endian UInt64 byte count followed by the raw little-endian values.
//   Appended: the arrays follow `<AppendedData encoding="raw">` and an underscore, each
//             DataArray names its byte offset from that underscore (VTK/ParaView's default,
//             smallest and fastest; the file is then not well-formed XML).
//   Base64:   count and values base64-encoded together inside the DataArray element.
//   Ascii:    values as text, shortest round-trip decimal form.
// The root element must declare header_type="UInt64" for the binary encodings.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/output_file.h"

namespace tfd::io {

enum class VtkEncoding { Appended, Base64, Ascii };

/// Value types of VTK XML DataArrays that tfd writes.
enum class VtkType { UInt8, Int32, Int64, Float32, Float64 };
const char* vtkTypeName(VtkType type);  ///< "UInt8", "Int32", …

class VtkXmlWriter {
 public:
  using Attributes = std::vector<std::pair<std::string, std::string>>;

  explicit VtkXmlWriter(VtkEncoding encoding) : encoding_(encoding) {}

  /// Opens an element; close it with end().
  void begin(std::string_view tag, const Attributes& attributes = {});
  void end();

  /// A DataArray element of values.size() / components tuples. Extra attributes (e.g.
  /// ComponentName0) are added to the element.
  void dataArray(std::string_view name, int components, std::span<const std::uint8_t> values,
                 const Attributes& extra = {});
  void dataArray(std::string_view name, int components, std::span<const std::int32_t> values,
                 const Attributes& extra = {});
  void dataArray(std::string_view name, int components, std::span<const std::int64_t> values,
                 const Attributes& extra = {});
  void dataArray(std::string_view name, int components, std::span<const float> values,
                 const Attributes& extra = {});
  void dataArray(std::string_view name, int components, std::span<const double> values,
                 const Attributes& extra = {});

  /// Writes the document to `out` (from io::writeAtomically, which checks that every byte
  /// reached the disk). Only the root element may still be open; save() closes it (after the
  /// appended data).
  void save(OutputFile& out);

 private:
  void array(std::string_view name, VtkType type, int components, const void* data,
             std::size_t count, const Attributes& extra);
  void indent();

  VtkEncoding encoding_;
  std::string xml_;
  std::string appended_;
  std::vector<std::string> open_;
};

/// Escapes &, <, >, " and ' for use in an XML attribute value.
std::string xmlEscape(std::string_view text);

}  // namespace tfd::io
