// `tfd info` for the io layer's files: meshes, OpenVDB volumes, OpenEXR slices and
// degenerate-curve JSON. Each prints label/value rows (formatRows).
#include "apps/tfd/describe_io_files.h"

#include <iomanip>
#include <sstream>

#include "io/curves/curve_json_reader.h"
#include "io/volume/exr_reader.h"
#include "io/volume/vdb_reader.h"

namespace tfd::cli {
namespace {

template <class T>
std::string joined(const T& values, const char* separator = " ") {
  std::ostringstream s;
  s << std::setprecision(6);
  bool first = true;
  for (const auto& v : values) {
    if (!first) s << separator;
    s << v;
    first = false;
  }
  return s.str();
}

std::string boxText(const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  std::ostringstream s;
  s << "[" << joined(lo, ", ") << "] .. [" << joined(hi, ", ") << "]";
  return s.str();
}

}  // namespace

std::string formatRows(const Rows& rows) {
  std::size_t width = 0;
  for (const auto& [label, value] : rows) width = std::max(width, label.size());
  std::string out;
  for (const auto& [label, value] : rows) {
    // An empty label continues the row above (a list of values under one label).
    out += label.empty() ? std::string(width + 2, ' ')
                         : label + ":" + std::string(width - label.size() + 1, ' ');
    out += value + "\n";
  }
  return out;
}

int describeMesh(const std::filesystem::path& file, std::ostream& out) {
  out << formatRows(describeMeshFile(file));
  return 0;
}

int describeVdb(const std::filesystem::path& file, std::ostream& out) {
  const io::VdbFileData data = io::readVdbMetadata(file);
  Rows rows{{"format", "OpenVDB volume"}, {"grids", std::to_string(data.grids.size())}};
  for (const auto& [key, value] : data.fileMetadata) rows.push_back({"metadata " + key, value});
  for (const io::VdbGridData& g : data.grids) {
    std::ostringstream s;
    s << std::setprecision(6) << g.valueType;
    if (g.valueType.starts_with("vec")) s << " (" << g.vectorType << ")";
    s << ", " << g.gridClass << ", voxel "
      << joined(std::array{g.voxelSize.x(), g.voxelSize.y(), g.voxelSize.z()});
    if (!g.activeVoxelsKnown) {
      s << ", active voxels not recorded";
    } else {
      s << ", " << g.activeVoxelCount << " active voxels";
      if (g.activeVoxelCount > 0 && g.activeMin[0] <= g.activeMax[0])
        s << " in " << boxText(g.activeMin, g.activeMax);
    }
    rows.push_back({"grid " + g.name, s.str()});
  }
  out << formatRows(rows);
  return 0;
}

int describeExr(const std::filesystem::path& file, std::ostream& out) {
  const io::ExrImage image = io::readExrImage(file);
  Rows rows{{"format", "OpenEXR image"},
            {"size", std::to_string(image.width) + " x " + std::to_string(image.height)}};
  std::vector<std::string> channels;
  for (const auto& [name, type] : image.channelTypes) channels.push_back(name + " (" + type + ")");
  rows.push_back({"channels", joined(channels, ", ")});
  for (const auto& [name, a] : image.attributes)
    if (name.starts_with("tfd."))
      rows.push_back({name, a.numbers.empty() ? a.text : joined(a.numbers)});
  out << formatRows(rows);
  return 0;
}

int describeCurvesJson(const std::filesystem::path& file, std::ostream& out) {
  const io::CurveFile curves = io::readCurvesJson(file);
  int linear = 0, planar = 0, loops = 0, points = 0, transitions = 0;
  for (const io::CurveFileEntry& c : curves.curves) {
    (c.type == core::DegenerateType::Linear ? linear : planar) += 1;
    loops += c.closed;
    points += static_cast<int>(c.points.size());
    for (auto p : c.patterns) transitions += p == core::DegeneratePattern::Transition;
  }
  out << formatRows(
      {{"format", "tfd degenerate curves, version " + std::to_string(curves.formatVersion)},
       {"curves", std::to_string(linear + planar) + " (" + std::to_string(linear) + " linear, " +
                      std::to_string(planar) + " planar; " + std::to_string(loops) + " loops)"},
       {"points",
        std::to_string(points) + ", " + std::to_string(transitions) + " transition points"}});
  return 0;
}

}  // namespace tfd::cli
