#pragma once
// Test-only reader of VTK XML files (.vtu, .vtp), written independently of io/vtk_xml so the
// writer is checked against the format, not against itself. Parses the XML (elements,
// attributes, text, entities, comments) and decodes DataArrays in the three encodings VTK
// uses without compression: ascii, inline base64 ("binary") and raw appended data, with
// UInt32 or UInt64 headers. Throws std::runtime_error on anything malformed.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tfd::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  ///< concatenated character data directly inside this element
  std::vector<XmlElement> children;

  /// The single child with this name; throws when there is none or several.
  const XmlElement& child(const std::string& childName) const;
  std::vector<const XmlElement*> childrenNamed(const std::string& childName) const;
  const std::string& attribute(const std::string& key) const;  ///< throws when missing
  bool has(const std::string& key) const { return attributes.count(key) > 0; }
};

struct VtkXmlFile {
  XmlElement root;          ///< the VTKFile element
  std::string appendedRaw;  ///< bytes after the '_' of <AppendedData encoding="raw">
  /// Values of a DataArray element converted to double (all components, tuple after tuple).
  std::vector<double> values(const XmlElement& dataArray) const;
  /// The DataArray named `name` among the children of `parent`.
  const XmlElement& array(const XmlElement& parent, const std::string& name) const;
};

VtkXmlFile readVtkXmlFile(const std::filesystem::path& path);

/// The XML parser alone, for documents without appended raw data.
XmlElement parseXml(const std::string& text);

}  // namespace tfd::test
