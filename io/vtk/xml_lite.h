#pragma once
// A small XML reader, enough for VTK XML files (.vtu): elements, attributes, character data,
// comments and the prolog; stops at <AppendedData> (raw bytes follow). Internal helper.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tfd::io {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<XmlElement> children;
  std::string text;  ///< character data directly inside, entities decoded
  int line = 0;      ///< line of the start tag, for messages

  /// The attribute's value, or nullptr.
  const std::string* attribute(std::string_view key) const;
  /// First child with this name, or nullptr.
  const XmlElement* child(std::string_view childName) const;
  std::vector<const XmlElement*> childrenNamed(std::string_view childName) const;
};

struct XmlDocument {
  XmlElement root;
  /// For VTK files: byte offset just after the '_' that starts the appended data, npos when
  /// there is no <AppendedData> element; and that element's attributes.
  std::size_t appendedStart = std::string::npos;
  XmlElement appended;
};

/// Parses `data`; throws core::Error "file 'x', line N: <problem>" on malformed XML.
XmlDocument parseXml(std::string_view data, const std::string& fileName);

}  // namespace tfd::io
