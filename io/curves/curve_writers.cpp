#include "io/curves/curve_writers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"

namespace tfd::io {
namespace {

using core::DegenerateCurves;
using core::DegeneratePattern;
using core::DegenerateType;

void writeText(const std::filesystem::path& path, const std::string& text) {
  writeAtomically(path, [&](OutputFile& out) { out.write(text.data(), text.size()); });
}

/// Shortest decimal that reads back to the same double.
void appendNumber(std::string& s, double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  s.append(buffer, r.ptr);
}

int patternCode(DegeneratePattern p) {
  return p == DegeneratePattern::Wedge ? 1 : p == DegeneratePattern::Trisector ? -1 : 0;
}

}  // namespace

void writeCurvesJson(const std::filesystem::path& path, const DegenerateCurves& curves) {
  nlohmann::ordered_json doc;
  doc["format"] = "tfd-degenerate-curves";
  doc["formatVersion"] = 1;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const core::DegenerateCurve& c : curves.curves()) {
    nlohmann::ordered_json j;
    j["id"] = c.id;
    j["type"] = core::toString(c.type);
    j["closed"] = c.closed;
    nlohmann::ordered_json points = nlohmann::ordered_json::array();
    for (const core::Vec3& p : c.points) points.push_back({p.x(), p.y(), p.z()});
    j["points"] = std::move(points);
    nlohmann::ordered_json pattern = nlohmann::ordered_json::array();
    for (DegeneratePattern p : c.patterns) pattern.push_back(core::toString(p));
    j["pattern"] = std::move(pattern);
    list.push_back(std::move(j));
  }
  doc["curves"] = std::move(list);
  writeText(path, doc.dump(1) + "\n");
}

void writeCurvesVtp(const std::filesystem::path& path, const DegenerateCurves& curves,
                    VtkEncoding encoding) {
  std::vector<double> points, tangents, eigenvectors;
  std::vector<std::int32_t> type, pattern, pointCurve, cellCurve, cellType;
  std::vector<std::uint8_t> colour, closed;
  std::vector<std::int64_t> connectivity, offsets;
  std::int64_t base = 0;
  for (const core::DegenerateCurve& c : curves.curves()) {
    const std::size_t n = c.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        points.push_back(c.points[i][k]);
        tangents.push_back(c.tangents[i][k]);
        eigenvectors.push_back(c.eigenvectors[i][k]);
      }
      type.push_back(c.type == DegenerateType::Linear ? 1 : -1);
      pattern.push_back(patternCode(c.patterns[i]));
      for (std::uint8_t v : core::fig5Colour(c.type, c.patterns[i])) colour.push_back(v);
      pointCurve.push_back(c.id);
      connectivity.push_back(base + std::int64_t(i));
    }
    if (c.closed && n > 1) connectivity.push_back(base);
    offsets.push_back(std::int64_t(connectivity.size()));
    cellCurve.push_back(c.id);
    cellType.push_back(c.type == DegenerateType::Linear ? 1 : -1);
    closed.push_back(c.closed ? 1 : 0);
    base += std::int64_t(n);
  }
  VtkXmlWriter xml(encoding);
  xml.begin("VTKFile", {{"type", "PolyData"},
                        {"version", "1.0"},
                        {"byte_order", "LittleEndian"},
                        {"header_type", "UInt64"}});
  xml.begin("PolyData");
  xml.begin("Piece", {{"NumberOfPoints", std::to_string(base)},
                      {"NumberOfVerts", "0"},
                      {"NumberOfLines", std::to_string(curves.size())},
                      {"NumberOfStrips", "0"},
                      {"NumberOfPolys", "0"}});
  // `colour` (Fig. 5 RGB) is the active scalars, so ParaView colours the curves as the paper
  // does when the file is opened; `pattern` keeps the per-point pattern as numbers.
  xml.begin("PointData", {{"Scalars", "colour"}, {"Vectors", "tangent"}});
  xml.dataArray("type", 1, std::span<const std::int32_t>(type));
  xml.dataArray("pattern", 1, std::span<const std::int32_t>(pattern));
  xml.dataArray("colour", 3, std::span<const std::uint8_t>(colour));
  xml.dataArray("tangent", 3, std::span<const double>(tangents));
  xml.dataArray("eigenvector", 3, std::span<const double>(eigenvectors));
  xml.dataArray("curve_id", 1, std::span<const std::int32_t>(pointCurve));
  xml.end();
  xml.begin("CellData", {{"Scalars", "curve_id"}});
  xml.dataArray("curve_id", 1, std::span<const std::int32_t>(cellCurve));
  xml.dataArray("type", 1, std::span<const std::int32_t>(cellType));
  xml.dataArray("closed", 1, std::span<const std::uint8_t>(closed));
  xml.end();
  xml.begin("Points");
  xml.dataArray("Points", 3, std::span<const double>(points));
  xml.end();
  xml.begin("Lines");
  xml.dataArray("connectivity", 1, std::span<const std::int64_t>(connectivity));
  xml.dataArray("offsets", 1, std::span<const std::int64_t>(offsets));
  xml.end();
  xml.end();  // Piece
  xml.end();  // PolyData
  writeAtomically(path, [&](OutputFile& out) { xml.save(out); });
}

void writeCurvesObj(const std::filesystem::path& path, const DegenerateCurves& curves) {
  std::string s = "# tfd degenerate curves: " + curves.summary() + "\n";
  for (const core::DegenerateCurve& c : curves.curves()) {
    for (const core::Vec3& p : c.points) {
      s += "v ";
      appendNumber(s, p.x());
      s += ' ';
      appendNumber(s, p.y());
      s += ' ';
      appendNumber(s, p.z());
      s += '\n';
    }
  }
  std::size_t base = 1;
  for (const core::DegenerateCurve& c : curves.curves()) {
    const std::size_t n = c.points.size();
    s += "o curve_";
    s += std::to_string(c.id);
    s += '_';
    s += core::toString(c.type);
    s += '\n';
    // One two-point `l` element per segment: Blender's importer (3.4) keeps only the first
    // segment of a longer `l` element; every OBJ reader takes these.
    const auto segment = [&](std::size_t a, std::size_t b) {
      s += "l ";
      s += std::to_string(a);
      s += ' ';
      s += std::to_string(b);
      s += '\n';
    };
    for (std::size_t i = 0; i + 1 < n; ++i) segment(base + i, base + i + 1);
    if (c.closed && n > 2) segment(base + n - 1, base);
    base += n;
  }
  writeText(path, s);
}

void writeCurves(const std::filesystem::path& path, const DegenerateCurves& curves,
                 const CurveWriteOptions& options) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  if (ext == ".json") return writeCurvesJson(path, curves);
  if (ext == ".vtp") return writeCurvesVtp(path, curves, options.vtpEncoding);
  if (ext == ".obj") return writeCurvesObj(path, curves);
  throw core::Error("cannot write degenerate curves to '" + path.string() +
                    "': unknown extension '" + ext + "' (use .json, .vtp or .obj)");
}

}  // namespace tfd::io
