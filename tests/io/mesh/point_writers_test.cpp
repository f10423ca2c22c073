// Instance points to PLY: the header names Houdini's attributes in the documented order, and
// the values read back (binary little and big endian, ASCII) with a reader written here from
// the PLY specification, not tfd's own.
#include "io/mesh/point_writers.h"

#include <gtest/gtest.h>

#include <sstream>

#include "io/binary_io.h"
#include "io/file_bytes.h"
#include "tests/support/temp_dir.h"

namespace tfd::io {
namespace {

core::InstancePoints samplePoints() {
  core::InstancePoints pts;
  for (int i = 0; i < 5; ++i) {
    core::InstancePoint p;
    p.position = core::Vec3(i / 3.0, -i * 1e-3, 7 + i);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3 * i, core::Vec3(1, i, 2).normalized()));
    p.orient = {q.w(), q.x(), q.y(), q.z()};
    p.scale = core::Vec3(0.1, 0.2, 0.05 * (i + 1));
    p.kind = i % 2 ? core::ElementKind::Box : core::ElementKind::Line;
    pts.points.push_back(p);
  }
  return pts;
}

const std::vector<std::string> kProperties = {"double x",       "double y",       "double z",
                                              "float orient_x", "float orient_y", "float orient_z",
                                              "float orient_w", "float pscale",   "float scale_x",
                                              "float scale_y",  "float scale_z",  "uchar kind"};

struct Read {
  std::vector<std::string> properties;
  std::string format;
  std::vector<std::vector<double>> rows;
};

Read readPointsPly(const std::filesystem::path& path) {
  const std::string bytes = readFileBytes(path);
  const std::size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  Read r;
  std::string line;
  std::size_t count = 0;
  while (std::getline(header, line)) {
    if (line.rfind("format ", 0) == 0) r.format = line.substr(7);
    if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    if (line.rfind("element ", 0) == 0 && line.rfind("element vertex ", 0) != 0)
      ADD_FAILURE() << "unexpected element: " << line;
    if (line.rfind("property ", 0) == 0) r.properties.push_back(line.substr(9));
  }
  const char* p = bytes.data() + end + 11;
  if (r.format == "ascii 1.0") {
    std::istringstream body(std::string(p, bytes.data() + bytes.size()));
    for (std::size_t i = 0; i < count; ++i) {
      std::vector<double> row(12);
      for (double& v : row) body >> v;
      r.rows.push_back(row);
    }
    return r;
  }
  const Endian e = r.format == "binary_little_endian 1.0" ? Endian::Little : Endian::Big;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<double> row;
    for (int k = 0; k < 3; ++k, p += 8) row.push_back(loadScalar<double>(p, e));
    for (int k = 0; k < 8; ++k, p += 4) row.push_back(loadScalar<float>(p, e));
    row.push_back(double(std::uint8_t(*p++)));
    r.rows.push_back(row);
  }
  EXPECT_EQ(p, bytes.data() + bytes.size()) << "no bytes left over";
  return r;
}

TEST(PointWriters, InstancePointsReadBackInEveryEncoding) {
  test::TempDir dir("point-writers");
  const core::InstancePoints pts = samplePoints();
  for (PlyEncoding enc :
       {PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian, PlyEncoding::Ascii}) {
    const auto path = dir.path() / "points.ply";
    writeInstancePointsPly(path, pts, enc);
    const Read r = readPointsPly(path);
    EXPECT_EQ(r.properties, kProperties);
    ASSERT_EQ(r.rows.size(), pts.points.size());
    for (std::size_t i = 0; i < pts.points.size(); ++i) {
      const core::InstancePoint& p = pts.points[i];
      const auto& row = r.rows[i];
      for (int k = 0; k < 3; ++k) EXPECT_EQ(row[k], p.position[k]) << "exact positions";
      // Houdini's order: x, y, z, then w.
      EXPECT_NEAR(row[3], p.orient[1], 1e-7);
      EXPECT_NEAR(row[4], p.orient[2], 1e-7);
      EXPECT_NEAR(row[5], p.orient[3], 1e-7);
      EXPECT_NEAR(row[6], p.orient[0], 1e-7);
      EXPECT_NEAR(row[7], p.scale.maxCoeff(), 1e-7);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(row[8 + k], p.scale[k], 1e-7);
      EXPECT_EQ(row[11], p.kind == core::ElementKind::Box ? 1 : 0);
    }
  }
}

TEST(PointWriters, AnUnwritablePathNamesTheFile) {
  test::TempDir dir("point-writers-bad");
  try {
    writeInstancePointsPly(dir.path(), samplePoints());
    FAIL() << "wrote to a folder";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find(dir.path().string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tfd::io
