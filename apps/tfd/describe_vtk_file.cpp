// `tfd info` of VTK XML files: a .vtu as a tet mesh plus its point and cell arrays, a .vtp
// (curves, lines) by its counts and arrays.
#include "apps/tfd/describe_io_files.h"

#include <ostream>

#include "io/vtk/vtk_xml_summary.h"

namespace tfd::cli {
namespace {

/// "T (Float64 × 6, active tensors)".
std::string arrayText(const io::VtkArraySummary& a) {
  std::string s = a.name + " (" + a.type;
  if (a.components != 1) s += " × " + std::to_string(a.components);
  if (!a.active.empty()) s += ", active " + a.active;
  return s + ")";
}

void addArrays(Rows& rows, const std::string& label,
               const std::vector<io::VtkArraySummary>& arrays) {
  if (arrays.empty()) {
    rows.emplace_back(label, "none");
    return;
  }
  for (std::size_t i = 0; i < arrays.size(); ++i)
    rows.emplace_back(i == 0 ? label : "", arrayText(arrays[i]));
}

void addSummaryRows(Rows& rows, const io::VtkXmlSummary& s) {
  std::string encoding = s.encoding.empty() ? "none" : s.encoding;
  if (!s.compressor.empty()) encoding += ", " + s.compressor;
  rows.emplace_back("encoding", encoding);
  addArrays(rows, "point arrays", s.pointArrays);
  addArrays(rows, "cell arrays", s.cellArrays);
}

}  // namespace

int describeVtu(const std::filesystem::path& file, std::ostream& out) {
  Rows rows = describeMeshFile(file);
  addSummaryRows(rows, io::summarizeVtkXml(file));
  out << formatRows(rows);
  return 0;
}

int describeVtp(const std::filesystem::path& file, std::ostream& out) {
  const io::VtkXmlSummary s = io::summarizeVtkXml(file);
  Rows rows{{"format", "VTK XML " + s.dataset + " (.vtp)"},
            {"points", std::to_string(s.points)},
            {"lines", std::to_string(s.lines)},
            {"polygons", std::to_string(s.polys)},
            {"vertices", std::to_string(s.verts)}};
  if (s.strips > 0) rows.emplace_back("strips", std::to_string(s.strips));
  addSummaryRows(rows, s);
  out << formatRows(rows);
  return 0;
}

}  // namespace tfd::cli
