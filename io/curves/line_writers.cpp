#include "io/curves/line_writers.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/text_format.h"

namespace tfd::io {
namespace {

/// Per-point and per-line arrays of the .vtp file.
struct LineArrays {
  std::vector<double> points, eigenvalues, arc, cellLength;
  std::array<std::vector<double>, 3> single;
  std::vector<std::int32_t> pointLine, cellLine, startStop, endStop;
  std::vector<std::int64_t> connectivity, offsets;
};

LineArrays collect(const core::Polylines& lines) {
  LineArrays a;
  std::int64_t base = 0;
  for (std::size_t l = 0; l < lines.lines.size(); ++l) {
    const core::Polyline& line = lines.lines[l];
    double s = 0;
    for (std::size_t i = 0; i < line.points.size(); ++i) {
      if (i > 0) s += (line.points[i] - line.points[i - 1]).norm();
      const core::Vec3 e = i < line.eigenvalues.size() ? line.eigenvalues[i] : core::Vec3::Zero();
      for (int k = 0; k < 3; ++k) {
        a.points.push_back(line.points[i][k]);
        a.eigenvalues.push_back(e[k]);
        a.single[k].push_back(e[k]);
      }
      a.arc.push_back(s);
      a.pointLine.push_back(std::int32_t(l));
      a.connectivity.push_back(base + std::int64_t(i));
    }
    base += std::int64_t(line.points.size());
    a.offsets.push_back(base);
    a.cellLine.push_back(std::int32_t(l));
    a.cellLength.push_back(s);
    a.startStop.push_back(static_cast<std::int32_t>(line.stops[0]));
    a.endStop.push_back(static_cast<std::int32_t>(line.stops[1]));
  }
  return a;
}

}  // namespace

void writeLinesVtp(const std::filesystem::path& path, const core::Polylines& lines,
                   VtkEncoding encoding) {
  const LineArrays a = collect(lines);
  using S = std::span<const double>;
  using I = std::span<const std::int32_t>;
  VtkXmlWriter xml(encoding);
  xml.begin("VTKFile", {{"type", "PolyData"},
                        {"version", "1.0"},
                        {"byte_order", "LittleEndian"},
                        {"header_type", "UInt64"}});
  xml.begin("PolyData");
  xml.begin("FieldData");
  // The followed eigenvector as a one-value array: 0 major, 1 medium, 2 minor.
  const std::int32_t family[] = {static_cast<std::int32_t>(lines.family)};
  xml.dataArray("family", 1, I(family), {{"NumberOfTuples", "1"}});
  xml.end();
  xml.begin("Piece", {{"NumberOfPoints", std::to_string(a.pointLine.size())},
                      {"NumberOfVerts", "0"},
                      {"NumberOfLines", std::to_string(lines.lines.size())},
                      {"NumberOfStrips", "0"},
                      {"NumberOfPolys", "0"}});
  xml.begin("PointData", {{"Scalars", "eigenvalues"}});
  xml.dataArray(
      "eigenvalues", 3, S(a.eigenvalues),
      {{"ComponentName0", "major"}, {"ComponentName1", "medium"}, {"ComponentName2", "minor"}});
  xml.dataArray("major", 1, S(a.single[0]));
  xml.dataArray("medium", 1, S(a.single[1]));
  xml.dataArray("minor", 1, S(a.single[2]));
  xml.dataArray("arc_length", 1, S(a.arc));
  xml.dataArray("line_id", 1, I(a.pointLine));
  xml.end();
  xml.begin("CellData", {{"Scalars", "line_id"}});
  xml.dataArray("line_id", 1, I(a.cellLine));
  xml.dataArray("length", 1, S(a.cellLength));
  xml.dataArray("start_stop", 1, I(a.startStop));
  xml.dataArray("end_stop", 1, I(a.endStop));
  xml.end();
  xml.begin("Points");
  xml.dataArray("Points", 3, S(a.points));
  xml.end();
  xml.begin("Lines");
  xml.dataArray("connectivity", 1, std::span<const std::int64_t>(a.connectivity));
  xml.dataArray("offsets", 1, std::span<const std::int64_t>(a.offsets));
  xml.end();
  xml.end();  // Piece
  xml.end();  // PolyData
  writeAtomically(path, [&](OutputFile& out) { xml.save(out); });
}

void writeLinesObj(const std::filesystem::path& path, const core::Polylines& lines) {
  std::string s = "# tfd lines: " + lines.summary() + "\n";
  for (const core::Polyline& line : lines.lines)
    for (const core::Vec3& p : line.points) {
      s += "v ";
      appendNumber(s, p.x());
      s += ' ';
      appendNumber(s, p.y());
      s += ' ';
      appendNumber(s, p.z());
      s += '\n';
    }
  std::size_t base = 1;
  for (std::size_t l = 0; l < lines.lines.size(); ++l) {
    const std::size_t n = lines.lines[l].points.size();
    s += "o line_";
    appendNumber(s, l);
    s += '\n';
    for (std::size_t i = 0; i + 1 < n; ++i) {
      s += "l ";
      appendNumber(s, base + i);
      s += ' ';
      appendNumber(s, base + i + 1);
      s += '\n';
    }
    base += n;
  }
  writeAtomically(path, [&](OutputFile& out) { out.write(s.data(), s.size()); });
}

void writeLines(const std::filesystem::path& path, const core::Polylines& lines,
                VtkEncoding vtpEncoding) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  if (ext == ".vtp") return writeLinesVtp(path, lines, vtpEncoding);
  if (ext == ".obj") return writeLinesObj(path, lines);
  throw core::Error("cannot write lines to '" + path.string() + "': unknown extension '" + ext +
                    "' (use .vtp or .obj)");
}

}  // namespace tfd::io
