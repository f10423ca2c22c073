#include "tests/support/vtk_xml_reader.h"

#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tfd::test {

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  XmlElement document() {
    skipMisc();
    XmlElement root = element();
    skipMisc();
    if (pos_ != s_.size()) fail("XML: content after the root element at " + std::to_string(pos_));
    return root;
  }

 private:
  bool starts(const char* prefix) const {
    return s_.compare(pos_, std::strlen(prefix), prefix) == 0;
  }
  void skipSpace() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  void skipPast(const char* terminator) {
    const auto end = s_.find(terminator, pos_);
    if (end == std::string::npos) fail(std::string("XML: missing ") + terminator);
    pos_ = end + std::strlen(terminator);
  }
  // Prolog, comments and whitespace between elements.
  void skipMisc() {
    for (;;) {
      skipSpace();
      if (starts("<?"))
        skipPast("?>");
      else if (starts("<!--"))
        skipPast("-->");
      else
        return;
    }
  }
  std::string name() {
    const std::size_t begin = pos_;
    while (pos_ < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_' ||
            s_[pos_] == ':' || s_[pos_] == '-' || s_[pos_] == '.')) {
      ++pos_;
    }
    if (pos_ == begin) fail("XML: expected a name at " + std::to_string(pos_));
    return s_.substr(begin, pos_ - begin);
  }
  static std::string decode(const std::string& raw) {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      const auto end = raw.find(';', i);
      if (end == std::string::npos) fail("XML: unterminated entity");
      const std::string entity = raw.substr(i + 1, end - i - 1);
      if (entity == "amp")
        out += '&';
      else if (entity == "lt")
        out += '<';
      else if (entity == "gt")
        out += '>';
      else if (entity == "quot")
        out += '"';
      else if (entity == "apos")
        out += '\'';
      else
        fail("XML: unknown entity &" + entity + ";");
      i = end;
    }
    return out;
  }
  XmlElement element() {
    if (!starts("<")) fail("XML: expected '<' at " + std::to_string(pos_));
    ++pos_;
    XmlElement e;
    e.name = name();
    for (;;) {
      skipSpace();
      if (starts("/>")) {
        pos_ += 2;
        return e;
      }
      if (starts(">")) {
        ++pos_;
        break;
      }
      const std::string key = name();
      skipSpace();
      if (!starts("=")) fail("XML: expected '=' after attribute " + key);
      ++pos_;
      skipSpace();
      const char quote = pos_ < s_.size() ? s_[pos_] : 0;
      if (quote != '"' && quote != '\'') fail("XML: attribute " + key + " is not quoted");
      const auto end = s_.find(quote, pos_ + 1);
      if (end == std::string::npos) fail("XML: unterminated attribute " + key);
      if (!e.attributes.emplace(key, decode(s_.substr(pos_ + 1, end - pos_ - 1))).second) {
        fail("XML: attribute " + key + " repeated in <" + e.name + ">");
      }
      pos_ = end + 1;
    }
    for (;;) {
      if (pos_ >= s_.size()) fail("XML: element <" + e.name + "> is not closed");
      if (starts("<!--")) {
        skipPast("-->");
      } else if (starts("</")) {
        pos_ += 2;
        const std::string closing = name();
        if (closing != e.name) fail("XML: <" + e.name + "> closed by </" + closing + ">");
        skipSpace();
        if (!starts(">")) fail("XML: expected '>' after </" + closing);
        ++pos_;
        return e;
      } else if (starts("<")) {
        e.children.push_back(element());
      } else {
        const auto end = s_.find('<', pos_);
        if (end == std::string::npos) fail("XML: element <" + e.name + "> is not closed");
        e.text += decode(s_.substr(pos_, end - pos_));
        pos_ = end;
      }
    }
  }

  const std::string& s_;
  std::size_t pos_ = 0;
};

std::vector<unsigned char> base64Decode(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else if (c == '=')
      break;
    else if (std::isspace(static_cast<unsigned char>(c)))
      continue;
    else
      fail(std::string("base64: bad character '") + c + "'");
    buffer = (buffer << 6) | unsigned(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return out;
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // the tests run on little-endian machines, like the files
  return v;
}

std::size_t sizeOf(const std::string& type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  fail("VTK: unknown DataArray type " + type);
}

double valueAt(const std::string& type, const unsigned char* p) {
  if (type == "Int8") return load<std::int8_t>(p);
  if (type == "UInt8") return load<std::uint8_t>(p);
  if (type == "Int16") return load<std::int16_t>(p);
  if (type == "UInt16") return load<std::uint16_t>(p);
  if (type == "Int32") return load<std::int32_t>(p);
  if (type == "UInt32") return load<std::uint32_t>(p);
  if (type == "Int64") return double(load<std::int64_t>(p));
  if (type == "UInt64") return double(load<std::uint64_t>(p));
  if (type == "Float32") return load<float>(p);
  if (type == "Float64") return load<double>(p);
  fail("VTK: unknown DataArray type " + type);
}

}  // namespace

const XmlElement& XmlElement::child(const std::string& childName) const {
  const auto all = childrenNamed(childName);
  if (all.size() != 1) {
    fail("<" + name + "> has " + std::to_string(all.size()) + " <" + childName + "> children");
  }
  return *all.front();
}

std::vector<const XmlElement*> XmlElement::childrenNamed(const std::string& childName) const {
  std::vector<const XmlElement*> out;
  for (const auto& c : children) {
    if (c.name == childName) out.push_back(&c);
  }
  return out;
}

const std::string& XmlElement::attribute(const std::string& key) const {
  const auto it = attributes.find(key);
  if (it == attributes.end()) fail("<" + name + "> has no attribute " + key);
  return it->second;
}

XmlElement parseXml(const std::string& text) { return Parser(text).document(); }

VtkXmlFile readVtkXmlFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open " + path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  VtkXmlFile file;
  const auto appended = text.find("<AppendedData");
  if (appended != std::string::npos) {
    const auto tagEnd = text.find('>', appended);
    const auto underscore = text.find('_', tagEnd);
    const auto close = text.rfind("</AppendedData>");
    if (tagEnd == std::string::npos || underscore == std::string::npos ||
        close == std::string::npos || close < underscore) {
      fail("VTK: malformed AppendedData section");
    }
    const XmlElement tag = parseXml(text.substr(appended, tagEnd - appended) + "/>");
    if (tag.attribute("encoding") != "raw") fail("VTK: appended data is not raw");
    for (auto i = tagEnd + 1; i < underscore; ++i) {
      if (!std::isspace(static_cast<unsigned char>(text[i]))) fail("VTK: junk before '_'");
    }
    file.appendedRaw = text.substr(underscore + 1, close - underscore - 1);
    text = text.substr(0, appended) + "<AppendedData encoding=\"raw\"/>" +
           text.substr(close + std::strlen("</AppendedData>"));
  }
  file.root = parseXml(text);
  if (file.root.name != "VTKFile") fail("VTK: root element is <" + file.root.name + ">");
  return file;
}

const XmlElement& VtkXmlFile::array(const XmlElement& parent, const std::string& name) const {
  const XmlElement* found = nullptr;
  for (const auto* a : parent.childrenNamed("DataArray")) {
    if (a->has("Name") && a->attribute("Name") == name) {
      if (found) fail("VTK: two arrays named " + name);
      found = a;
    }
  }
  if (!found) fail("VTK: no array named " + name + " in <" + parent.name + ">");
  return *found;
}

std::vector<double> VtkXmlFile::values(const XmlElement& a) const {
  const std::string& type = a.attribute("type");
  const std::string& format = a.attribute("format");
  const std::size_t word = sizeOf(type);
  std::vector<double> out;
  if (format == "ascii") {
    std::istringstream in(a.text);
    std::string token;
    while (in >> token) {
      std::size_t used = 0;
      const double v = std::stod(token, &used);
      if (used != token.size()) fail("VTK: bad ascii value " + token);
      out.push_back(v);
    }
  } else {
    const std::string headerType =
        root.has("header_type") ? root.attribute("header_type") : std::string("UInt32");
    const std::size_t headerSize = headerType == "UInt64" ? 8 : 4;
    if (headerType != "UInt64" && headerType != "UInt32") fail("VTK: bad header_type");
    if (root.has("compressor")) fail("VTK: compressed data is not supported by this reader");
    std::vector<unsigned char> bytes;
    std::size_t begin = 0;
    if (format == "binary") {
      bytes = base64Decode(a.text);
    } else if (format == "appended") {
      begin = std::stoull(a.attribute("offset"));
      bytes.assign(appendedRaw.begin(), appendedRaw.end());
    } else {
      fail("VTK: unknown DataArray format " + format);
    }
    if (begin + headerSize > bytes.size()) fail("VTK: data header out of range");
    const std::uint64_t count = headerSize == 8 ? load<std::uint64_t>(bytes.data() + begin)
                                                : load<std::uint32_t>(bytes.data() + begin);
    begin += headerSize;
    if (count % word != 0 || begin + count > bytes.size()) fail("VTK: bad data byte count");
    for (std::size_t i = 0; i < count; i += word)
      out.push_back(valueAt(type, bytes.data() + begin + i));
  }
  const int components =
      a.has("NumberOfComponents") ? std::stoi(a.attribute("NumberOfComponents")) : 1;
  if (out.size() % std::size_t(components) != 0) fail("VTK: values not a multiple of components");
  return out;
}

}  // namespace tfd::test
