#include "io/vtk/vtk_xml.h"

#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace tfd::io {

static_assert(std::endian::native == std::endian::little,
              "the VTK writer emits byte_order=\"LittleEndian\" and copies memory as is");

namespace {

std::size_t typeSize(VtkType type) {
  switch (type) {
    case VtkType::UInt8:
      return 1;
    case VtkType::Int32:
      return 4;
    case VtkType::Float32:
      return 4;
    case VtkType::Int64:
      return 8;
    case VtkType::Float64:
      return 8;
  }
  return 1;
}

void appendBase64(std::string& out, const unsigned char* data, std::size_t n) {
  static constexpr char alphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const unsigned v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i < n) {
    const unsigned v = (data[i] << 16) | (i + 1 < n ? data[i + 1] << 8 : 0);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += i + 1 < n ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
}

template <typename T>
void appendText(std::string& out, T value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void appendAscii(std::string& out, VtkType type, const void* data, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) out += (i % 9 == 0) ? '\n' : ' ';
    switch (type) {
      case VtkType::UInt8:
        appendText(out, int(static_cast<const std::uint8_t*>(data)[i]));
        break;
      case VtkType::Int32:
        appendText(out, static_cast<const std::int32_t*>(data)[i]);
        break;
      case VtkType::Int64:
        appendText(out, static_cast<const std::int64_t*>(data)[i]);
        break;
      case VtkType::Float32:
        appendText(out, static_cast<const float*>(data)[i]);
        break;
      case VtkType::Float64:
        appendText(out, static_cast<const double*>(data)[i]);
        break;
    }
  }
}

}  // namespace

const char* vtkTypeName(VtkType type) {
  switch (type) {
    case VtkType::UInt8:
      return "UInt8";
    case VtkType::Int32:
      return "Int32";
    case VtkType::Int64:
      return "Int64";
    case VtkType::Float32:
      return "Float32";
    case VtkType::Float64:
      return "Float64";
  }
  return "";
}

std::string xmlEscape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void VtkXmlWriter::indent() { xml_.append(2 * open_.size(), ' '); }

void VtkXmlWriter::begin(std::string_view tag, const Attributes& attributes) {
  if (open_.empty() && xml_.empty()) xml_ += "<?xml version=\"1.0\"?>\n";
  indent();
  xml_ += '<';
  xml_ += tag;
  for (const auto& [key, value] : attributes) {
    xml_ += ' ';
    xml_ += key;
    xml_ += "=\"";
    xml_ += xmlEscape(value);
    xml_ += '"';
  }
  xml_ += ">\n";
  open_.emplace_back(tag);
}

void VtkXmlWriter::end() {
  if (open_.empty()) throw core::Error("VTK XML writer: end() without an open element");
  const std::string tag = std::move(open_.back());
  open_.pop_back();
  indent();
  xml_ += "</" + tag + ">\n";
}

void VtkXmlWriter::array(std::string_view name, VtkType type, int components, const void* data,
                         std::size_t count, const Attributes& extra) {
  indent();
  xml_ += "<DataArray type=\"";
  xml_ += vtkTypeName(type);
  xml_ += "\" Name=\"" + xmlEscape(name) + "\" NumberOfComponents=\"" + std::to_string(components) +
          "\"";
  for (const auto& [key, value] : extra) xml_ += " " + key + "=\"" + xmlEscape(value) + "\"";
  const std::uint64_t bytes = count * typeSize(type);
  switch (encoding_) {
    case VtkEncoding::Appended: {
      xml_ += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
      appended_.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
      appended_.append(static_cast<const char*>(data), bytes);
      break;
    }
    case VtkEncoding::Base64: {
      xml_ += " format=\"binary\">\n";
      // The UInt64 byte count and the values form one base64 stream (VTK's layout when the
      // data is not compressed).
      std::string raw(reinterpret_cast<const char*>(&bytes), sizeof bytes);
      raw.append(static_cast<const char*>(data), bytes);
      indent();
      xml_ += "  ";
      appendBase64(xml_, reinterpret_cast<const unsigned char*>(raw.data()), raw.size());
      xml_ += '\n';
      indent();
      xml_ += "</DataArray>\n";
      break;
    }
    case VtkEncoding::Ascii: {
      xml_ += " format=\"ascii\">\n";
      appendAscii(xml_, type, data, count);
      xml_ += '\n';
      indent();
      xml_ += "</DataArray>\n";
      break;
    }
  }
}

void VtkXmlWriter::dataArray(std::string_view name, int components,
                             std::span<const std::uint8_t> values, const Attributes& extra) {
  array(name, VtkType::UInt8, components, values.data(), values.size(), extra);
}
void VtkXmlWriter::dataArray(std::string_view name, int components,
                             std::span<const std::int32_t> values, const Attributes& extra) {
  array(name, VtkType::Int32, components, values.data(), values.size(), extra);
}
void VtkXmlWriter::dataArray(std::string_view name, int components,
                             std::span<const std::int64_t> values, const Attributes& extra) {
  array(name, VtkType::Int64, components, values.data(), values.size(), extra);
}
void VtkXmlWriter::dataArray(std::string_view name, int components, std::span<const float> values,
                             const Attributes& extra) {
  array(name, VtkType::Float32, components, values.data(), values.size(), extra);
}
void VtkXmlWriter::dataArray(std::string_view name, int components, std::span<const double> values,
                             const Attributes& extra) {
  array(name, VtkType::Float64, components, values.data(), values.size(), extra);
}

void VtkXmlWriter::save(OutputFile& out) {
  if (open_.size() != 1) {
    throw core::Error("VTK XML writer: " + std::to_string(open_.size()) +
                      " elements open at save(), expected only the root");
  }
  std::ostream& s = out.stream();
  s.write(xml_.data(), std::streamsize(xml_.size()));
  if (!appended_.empty()) {
    s << "  <AppendedData encoding=\"raw\">\n   _";
    s.write(appended_.data(), std::streamsize(appended_.size()));
    s << "\n  </AppendedData>\n";
  }
  s << "</" << open_.back() << ">\n";
  open_.clear();
}

}  // namespace tfd::io
