// The VDB `density` grid: a fog volume of the chosen measure in [0, 1], checked against an
// independent eigenvalue computation, with OpenVDB's API and with OpenVDB's own `vdb_print`.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "core/structured_mesh.h"
#include "io/volume/vdb_reader.h"
#include "io/volume/vdb_writer.h"
#include "io/volume/voxel_density.h"
#include "tests/support/blend_field.h"
#include "tests/support/temp_dir.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;
using core::Tensor;
using core::Vec3;

using test::blendField;
using test::independentCloseness;
const auto blend = test::blendTensor;

fs::path writeBlend(const fs::path& dir, io::VoxelDensity measure) {
  const core::TensorField field = blendField();
  io::VdbExportOptions o;
  o.voxelSize = 0.05;
  o.quantities.eigenvectors = true;
  o.quantities.density = io::voxelDensityFunction(measure, field);
  const fs::path path = dir / "blend.vdb";
  io::writeFieldVdb(path, field, o);
  return path;
}

TEST(VdbDensity, DegeneracyIsAFogVolumeInZeroOneMatchingEigenvalues) {
  test::TempDir dir("vdb-density");
  const io::VdbFileData f = io::readVdbFile(writeBlend(dir.path(), io::VoxelDensity::Degeneracy));
  std::map<std::string, std::string> classes;
  for (const auto& g : f.grids) classes[g.name] = g.gridClass;
  EXPECT_EQ(classes, (std::map<std::string, std::string>{{"T.e1", "unknown"},
                                                         {"T.e2", "unknown"},
                                                         {"T.e3", "unknown"},
                                                         {"T.xx", "unknown"},
                                                         {"T.xy", "unknown"},
                                                         {"T.xz", "unknown"},
                                                         {"T.yy", "unknown"},
                                                         {"T.yz", "unknown"},
                                                         {"T.zz", "unknown"},
                                                         {"density", "fog volume"}}));
  double lo = 2, hi = -1;
  for (const auto& g : f.grids) {
    if (g.name != "density") continue;
    ASSERT_GT(g.activeVoxels.size(), 100u);
    for (const auto& v : g.activeVoxels) {
      const Vec3 p = g.indexOrigin + g.voxelSize.cwiseProduct(Vec3(v.ijk[0], v.ijk[1], v.ijk[2]));
      ASSERT_NEAR(v.value[0], independentCloseness(blend(p)), 2e-5) << p.transpose();
      lo = std::min(lo, v.value[0]);
      hi = std::max(hi, v.value[0]);
    }
  }
  // x = 0 is degenerate (1), x = 1 neutral (0); voxel centres reach both ends.
  EXPECT_GT(hi, 0.999);
  EXPECT_LT(lo, 0.001);
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
}

TEST(VdbDensity, AnisotropyIsNormalisedByTheLargestVertexDeviator) {
  test::TempDir dir("vdb-anisotropy");
  const io::VdbFileData f = io::readVdbFile(writeBlend(dir.path(), io::VoxelDensity::Anisotropy));
  double largest = 0;
  for (double x : {0.0, 1.0}) largest = std::max(largest, blend(Vec3(x, 0, 0)).deviator().norm());
  for (const auto& g : f.grids) {
    if (g.name != "density") continue;
    EXPECT_EQ(g.gridClass, "fog volume");
    for (const auto& v : g.activeVoxels) {
      const Vec3 p = g.indexOrigin + g.voxelSize.cwiseProduct(Vec3(v.ijk[0], v.ijk[1], v.ijk[2]));
      ASSERT_NEAR(v.value[0], blend(p).deviator().norm() / largest, 1e-5);
      ASSERT_LE(v.value[0], 1.0);
    }
  }
}

TEST(VdbDensity, NoneWritesNoDensityAndASignedScalarIsNoFogVolume) {
  test::TempDir dir("vdb-signed");
  const io::VdbFileData none = io::readVdbFile(writeBlend(dir.path(), io::VoxelDensity::None));
  for (const auto& g : none.grids) EXPECT_NE(g.name, "density");

  const core::TensorField field = blendField();
  std::vector<double> signedValues;
  for (const auto& p : field.mesh().positions()) signedValues.push_back(p.x() - 0.5);
  io::VdbExportOptions o;
  o.voxelSize = 0.05;
  o.quantities.density = io::interpolateVertexScalars(field.meshPtr(), signedValues);
  io::writeFieldVdb(dir.path() / "signed.vdb", field, o);
  for (const auto& g : io::readVdbFile(dir.path() / "signed.vdb").grids)
    EXPECT_EQ(g.gridClass, "unknown") << g.name;
}

/// `vdb_print -l` output split into sections by "Name: X".
std::map<std::string, std::string> vdbPrintSections(const fs::path& file) {
  const std::string command = "/usr/bin/vdb_print -l '" + file.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return {};
  std::string text;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, n);
  EXPECT_EQ(::pclose(pipe), 0) << text;
  std::map<std::string, std::string> sections;
  std::istringstream in(text);
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.starts_with("Name: ")) current = line.substr(6);
    if (!current.empty()) sections[current] += line + "\n";
  }
  return sections;
}

TEST(VdbDensity, VdbPrintListsDensityAsAFogVolume) {
  if (!fs::exists("/usr/bin/vdb_print"))
    GTEST_SKIP() << "/usr/bin/vdb_print not installed (Debian package libopenvdb-tools)";
  test::TempDir dir("vdb-print");
  const auto sections = vdbPrintSections(writeBlend(dir.path(), io::VoxelDensity::Degeneracy));
  ASSERT_EQ(sections.size(), 10u);
  ASSERT_TRUE(sections.count("density"));
  const std::string& density = sections.at("density");
  EXPECT_NE(density.find("class: fog volume"), std::string::npos) << density;
  EXPECT_NE(density.find("Type: Tree_float_5_4_3"), std::string::npos) << density;
  // vdb_print's own min / max of the active values: inside [0, 1], reaching both ends.
  const auto number = [&](const std::string& key) {
    const auto at = density.find(key);
    return at == std::string::npos ? -1.0 : std::stod(density.substr(at + key.size()));
  };
  EXPECT_GE(number("Min value: "), 0.0);
  EXPECT_LT(number("Min value: "), 0.001);
  EXPECT_GT(number("Max value: "), 0.999);
  EXPECT_LE(number("Max value: "), 1.0);
  EXPECT_NE(sections.at("T.xx").find("class: unknown"), std::string::npos) << sections.at("T.xx");
}

}  // namespace
}  // namespace tfd
