#include "io/vtk/vtk_xml_summary.h"

#include <charconv>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/vtk/xml_lite.h"

namespace tfd::io {
namespace {

std::int64_t count(const XmlElement& e, std::string_view key, const std::string& file) {
  const std::string* v = e.attribute(key);
  if (!v) return 0;
  std::int64_t n = -1;
  const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), n);
  if (ec != std::errc() || end != v->data() + v->size() || n < 0)
    throw core::Error("file '" + file + "', line " + std::to_string(e.line) + ": " +
                      std::string(key) + " is not a count");
  return n;
}

/// The arrays of a <PointData> or <CellData> element; `active` from its Scalars=... attributes.
std::vector<VtkArraySummary> arraysOf(const XmlElement* data, std::string& encoding) {
  std::vector<VtkArraySummary> out;
  if (!data) return out;
  for (const XmlElement* a : data->childrenNamed("DataArray")) {
    VtkArraySummary s;
    if (const auto* name = a->attribute("Name")) s.name = *name;
    if (const auto* type = a->attribute("type")) s.type = *type;
    if (const auto* n = a->attribute("NumberOfComponents")) s.components = std::atoi(n->c_str());
    for (const auto& [key, value] : data->attributes)
      if (value == s.name && s.active.empty()) s.active = key;
    const std::string format = a->attribute("format") ? *a->attribute("format") : "ascii";
    encoding = encoding.empty() || encoding == format ? format : "mixed";
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

VtkXmlSummary summarizeVtkXml(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string bytes = readFileBytes(path);
  const XmlDocument doc = parseXml(bytes, file);
  if (doc.root.name != "VTKFile")
    throw core::Error("file '" + file + "': not a VTK XML file (root element <" + doc.root.name +
                      ">)");
  VtkXmlSummary s;
  if (const auto* type = doc.root.attribute("type")) s.dataset = *type;
  if (const auto* c = doc.root.attribute("compressor")) s.compressor = *c;
  const XmlElement* dataset = doc.root.child(s.dataset);
  if (!dataset)
    throw core::Error("file '" + file + "': no <" + s.dataset + "> element under <VTKFile>");
  for (const XmlElement* piece : dataset->childrenNamed("Piece")) {
    ++s.pieces;
    s.points += count(*piece, "NumberOfPoints", file);
    s.cells += count(*piece, "NumberOfCells", file);
    s.verts += count(*piece, "NumberOfVerts", file);
    s.lines += count(*piece, "NumberOfLines", file);
    s.strips += count(*piece, "NumberOfStrips", file);
    s.polys += count(*piece, "NumberOfPolys", file);
    if (s.pieces == 1) {
      s.pointArrays = arraysOf(piece->child("PointData"), s.encoding);
      s.cellArrays = arraysOf(piece->child("CellData"), s.encoding);
    }
  }
  if (s.dataset == "PolyData") s.cells = s.verts + s.lines + s.strips + s.polys;
  return s;
}

}  // namespace tfd::io
