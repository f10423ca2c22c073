// OpenVDB export: files are read back with the OpenVDB library (io/vdb_reader) and checked for
// grid names, metadata, transform and values against analytic fields.
#include "io/volume/vdb_writer.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "io/volume/vdb_reader.h"
#include "tests/support/carved_ball.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;
using core::Tensor;
using core::Vec3;

/// Folder names get a per-file prefix so tests running in parallel never share one.
class TempDir : public test::TempDir {
 public:
  explicit TempDir(const std::string& name) : test::TempDir("vdb-" + name) {}
};

/// A linear tensor field T(p) = T0 + x Tx + y Ty + z Tz: P1 interpolation reproduces it exactly
/// (up to rounding), so every voxel can be checked against the formula. Its eigenvalues stay
/// well separated on the domains used below.
Tensor linearTensor(const Vec3& p) {
  return Tensor{3.0 + 0.5 * p.x(), 1.0 - 0.3 * p.y(),  -2.0 + 0.2 * p.z(),
                0.4 * p.y(),       0.25 + 0.1 * p.x(), -0.2 * p.z() + 0.05 * p.y()};
}
double linearDensity(const Vec3& p) { return 0.5 + 0.2 * p.x() - 0.1 * p.y() + 0.3 * p.z(); }

core::TensorField linearField(std::shared_ptr<const core::TetMesh> mesh) {
  std::vector<Tensor> values;
  for (const auto& p : mesh->positions()) values.push_back(linearTensor(p));
  return core::TensorField(std::move(mesh), std::move(values));
}

io::VdbExportOptions allQuantities(const core::TensorField& field, double voxelSize) {
  io::VdbExportOptions o;
  o.voxelSize = voxelSize;
  std::vector<double> density;
  for (const auto& p : field.mesh().positions()) density.push_back(linearDensity(p));
  o.quantities =
      io::VoxelQuantities{true, true, true, io::interpolateVertexScalars(field.meshPtr(), density)};
  o.source = "vdb_writer_test";
  return o;
}

const io::VdbGridData& grid(const io::VdbFileData& f, const std::string& name) {
  for (const auto& g : f.grids) {
    if (g.name == name) return g;
  }
  throw std::runtime_error("no grid " + name);
}

Vec3 worldOf(const io::VdbGridData& g, const std::array<int, 3>& ijk) {
  return g.indexOrigin + g.voxelSize.cwiseProduct(Vec3(ijk[0], ijk[1], ijk[2]));
}

/// Checks every active voxel of every grid against the analytic field.
void checkValues(const io::VdbFileData& f, std::size_t expectedActive) {
  const char* comps[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};
  for (int c = 0; c < 6; ++c) {
    const auto& g = grid(f, std::string("T.") + comps[c]);
    ASSERT_EQ(g.activeVoxels.size(), expectedActive) << g.name;
    EXPECT_EQ(g.inactiveNonBackground, 0u);
    for (const auto& v : g.activeVoxels) {
      const double expected = linearTensor(worldOf(g, v.ijk)).components()[c];
      ASSERT_NEAR(v.value[0], expected, 1e-6) << g.name;
    }
  }
  const auto& eigval = grid(f, "T.eigval");
  ASSERT_EQ(eigval.activeVoxels.size(), expectedActive);
  for (const auto& v : eigval.activeVoxels) {
    const auto e = core::eigenDecompose(linearTensor(worldOf(eigval, v.ijk)));
    for (int i = 0; i < 3; ++i) ASSERT_NEAR(v.value[i], e.values[i], 1e-6);
    ASSERT_GE(v.value[0], v.value[1]);
    ASSERT_GE(v.value[1], v.value[2]);
  }
  for (int i = 0; i < 3; ++i) {
    const auto& g = grid(f, "T.e" + std::to_string(i + 1));
    ASSERT_EQ(g.activeVoxels.size(), expectedActive);
    for (const auto& v : g.activeVoxels) {
      const Tensor t = linearTensor(worldOf(g, v.ijk));
      const auto e = core::eigenDecompose(t);
      const Vec3 got(v.value[0], v.value[1], v.value[2]);
      ASSERT_NEAR(got.norm(), 1.0, 1e-6);
      ASSERT_NEAR(std::abs(got.dot(e.vectors.col(i))), 1.0, 1e-5) << g.name;
      ASSERT_LT((t.matrix() * got - e.values[i] * got).norm(), 1e-5);
    }
  }
  const auto& density = grid(f, "density");
  ASSERT_EQ(density.activeVoxels.size(), expectedActive);
  for (const auto& v : density.activeVoxels) {
    ASSERT_NEAR(v.value[0], linearDensity(worldOf(density, v.ijk)), 1e-6);
  }
}

TEST(VdbWriter, BoxFieldGridsHaveNamesMetadataTransformAndAnalyticValues) {
  TempDir dir("box");
  const auto field = linearField(core::makeBoxMesh(4, 8, 3, Vec3(0, 0, 0), Vec3(1, 2, 0.75)));
  const fs::path path = dir.path() / "field.vdb";
  const auto stats = io::writeFieldVdb(path, field, allQuantities(field, 0.125));
  // Centres 0, 0.125, …: 9 x 17 x 7 voxels, all inside the box.
  EXPECT_EQ(stats.lattice.dims(), (std::array<int, 3>{9, 17, 7}));
  EXPECT_EQ(stats.activeVoxels, 9u * 17u * 7u);
  EXPECT_EQ(stats.filesWritten, 1);
  EXPECT_EQ(stats.files, std::vector<fs::path>{path});

  const io::VdbFileData f = io::readVdbFile(path);
  EXPECT_EQ(f.fileMetadata.at("generator"), "tfd");
  EXPECT_EQ(f.fileMetadata.at("source"), "vdb_writer_test");
  EXPECT_EQ(f.fileMetadata.at("tensor_components"), "xx,yy,zz,xy,yz,xz");
  std::vector<std::string> names;
  for (const auto& g : f.grids) names.push_back(g.name);
  std::sort(names.begin(), names.end());  // the reader's order is OpenVDB's, not the file's
  EXPECT_EQ(names, (std::vector<std::string>{"T.e1", "T.e2", "T.e3", "T.eigval", "T.xx", "T.xy",
                                             "T.xz", "T.yy", "T.yz", "T.zz", "density"}));
  for (const auto& g : f.grids) {
    SCOPED_TRACE(g.name);
    EXPECT_TRUE(g.linearTransform);
    EXPECT_EQ(g.voxelSize, Vec3::Constant(0.125));
    EXPECT_EQ(g.indexOrigin, Vec3::Zero());
    EXPECT_FALSE(g.saveFloatAsHalf);
    EXPECT_EQ(g.activeVoxelCount, 9u * 17u * 7u);
    EXPECT_EQ(g.activeMin, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(g.activeMax, (std::array<int, 3>{8, 16, 6}));
    EXPECT_EQ(g.background, (std::array<double, 3>{0, 0, 0}));
    const bool vector = g.name == "T.eigval" || g.name.starts_with("T.e");
    EXPECT_EQ(g.valueType, vector ? "vec3s" : "float");
    if (vector) {
      EXPECT_EQ(g.vectorType, "invariant");
    }
    if (g.name == "density") {
      EXPECT_EQ(g.gridClass, "fog volume");
      EXPECT_EQ(g.metadata.count("tensor_components"), 0u);
    } else {
      EXPECT_EQ(g.gridClass, "unknown");
      EXPECT_EQ(g.metadata.at("tensor_components"), "xx,yy,zz,xy,yz,xz");
    }
  }
  EXPECT_EQ(grid(f, "T.xy").metadata.at("component"), "xy");
  checkValues(f, 9u * 17u * 7u);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"field.vdb"});
}

TEST(VdbWriter, OriginShiftsVoxelCentres) {
  TempDir dir("origin");
  const auto field = linearField(core::makeBoxMesh(4, 4, 4, Vec3(0, 0, 0), Vec3(1, 1, 1)));
  auto options = allQuantities(field, 0.1);
  options.origin = Vec3(0.05, -0.02, 0.03);
  const auto stats = io::writeFieldVdb(dir.path() / "o.vdb", field, options);
  // x centres 0.05 … 0.95 (10), y −0.02 + 0.1 j for j = 1 … 10 (10), z 0.03 … 0.93 (10).
  EXPECT_EQ(stats.lattice.min, (std::array<int, 3>{0, 1, 0}));
  EXPECT_EQ(stats.lattice.max, (std::array<int, 3>{9, 10, 9}));
  const auto f = io::readVdbFile(dir.path() / "o.vdb");
  for (const auto& g : f.grids) EXPECT_TRUE(g.indexOrigin.isApprox(options.origin, 1e-15));
  checkValues(f, 1000);
}

/// True when p lies in some tet of the mesh, by brute force; `margin` reports how close p is
/// to deciding otherwise (the largest smallest barycentric coordinate).
bool insideBruteForce(const core::TetMesh& mesh, const Vec3& p, double& margin) {
  margin = -1e300;
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    margin = std::max(margin, mesh.barycentric(int(t), p).minCoeff());
  }
  return margin >= 0;
}

// `tfd info` reads only metadata (io/volume/vdb_reader.h says why): what it reports of the
// trees, from the statistics OpenVDB records with each grid, must be what the trees hold.
TEST(VdbWriter, MetadataAloneTellsWhatTheTreesHold) {
  TempDir dir("metadata");
  const auto field = linearField(test::carvedBall(6, Vec3(0.1, -0.2, 0.05), 1.0));
  auto options = allQuantities(field, 0.1);
  options.origin = Vec3(0.013, 0.027, 0.041);
  io::writeFieldVdb(dir.path() / "ball.vdb", field, options);
  const auto meta = io::readVdbMetadata(dir.path() / "ball.vdb");
  const auto full = io::readVdbFile(dir.path() / "ball.vdb", /*loadValues=*/false);
  EXPECT_EQ(meta.fileMetadata, full.fileMetadata);
  ASSERT_EQ(meta.grids.size(), full.grids.size());
  for (const auto& f : full.grids) {  // metadata lists the grids in name order
    SCOPED_TRACE(f.name);
    const auto& m = grid(meta, f.name);
    EXPECT_EQ(m.valueType, f.valueType);
    EXPECT_EQ(m.gridClass, f.gridClass);
    EXPECT_EQ(m.voxelSize, f.voxelSize);
    EXPECT_EQ(m.indexOrigin, f.indexOrigin);
    EXPECT_TRUE(m.activeVoxelsKnown);
    EXPECT_GT(f.activeVoxelCount, 100u);
    EXPECT_EQ(m.activeVoxelCount, f.activeVoxelCount);
    EXPECT_EQ(m.activeMin, f.activeMin);
    EXPECT_EQ(m.activeMax, f.activeMax);
  }
}

TEST(VdbWriter, OnlyVoxelsInsideACurvedVolumeAreActive) {
  TempDir dir("ball");
  const auto mesh = test::carvedBall(8, Vec3(0.1, -0.2, 0.05), 1.0);
  const auto field = linearField(mesh);
  auto options = allQuantities(field, 0.1);
  // Off-lattice origin: no voxel centre on a mesh face, so inside/outside is unambiguous.
  options.origin = Vec3(0.013, 0.027, 0.041);
  const auto stats = io::writeFieldVdb(dir.path() / "ball.vdb", field, options);
  const auto f = io::readVdbFile(dir.path() / "ball.vdb");
  const auto& xx = grid(f, "T.xx");
  std::set<std::array<int, 3>> active;
  for (const auto& v : xx.activeVoxels) active.insert(v.ijk);
  EXPECT_EQ(active.size(), stats.activeVoxels);
  const auto& L = stats.lattice;
  std::size_t inside = 0;
  for (int k = L.min[2]; k <= L.max[2]; ++k)
    for (int j = L.min[1]; j <= L.max[1]; ++j)
      for (int i = L.min[0]; i <= L.max[0]; ++i) {
        const Vec3 p = L.centre(i, j, k);
        double margin;
        const bool in = insideBruteForce(*mesh, p, margin);
        ASSERT_GT(std::abs(margin), 1e-9) << "ambiguous test point";
        ASSERT_EQ(active.count({i, j, k}), in ? 1u : 0u) << p.transpose();
        inside += in;
      }
  EXPECT_EQ(inside, stats.activeVoxels);
  EXPECT_GT(inside, 2000u);  // about 4/3 π / 0.001 ≈ 4189 minus the carved rim
  // Active voxels never beyond the ball (plus one cube diagonal of the carving).
  for (const auto& ijk : active) {
    EXPECT_LT((worldOf(xx, ijk) - Vec3(0.1, -0.2, 0.05)).norm(), 1.0 + 0.25 * std::sqrt(3.0));
  }
  checkValues(f, stats.activeVoxels);
}

TEST(VdbWriter, BadOptionsAndPathsFailWithClearErrorsAndNoFile) {
  TempDir dir("errors");
  const auto field = linearField(core::makeBoxMesh(2, 2, 2, Vec3(0, 0, 0), Vec3(1, 1, 1)));
  const fs::path path = dir.path() / "bad.vdb";
  for (double size : {0.0, -0.1, std::nan(""), HUGE_VAL}) {
    io::VdbExportOptions o;
    o.voxelSize = size;
    try {
      io::writeFieldVdb(path, field, o);
      FAIL() << "voxel size " << size << " accepted";
    } catch (const core::Error& e) {
      EXPECT_NE(std::string(e.what()).find("voxel size"), std::string::npos) << e.what();
    }
  }
  io::VdbExportOptions tiny;
  tiny.voxelSize = 1e-4;  // 10001³ voxels
  try {
    io::writeFieldVdb(path, field, tiny);
    FAIL() << "huge grid accepted";
  } catch (const core::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("voxel size 0.0001"), std::string::npos) << what;
    EXPECT_NE(what.find("limit"), std::string::npos) << what;
  }
  io::VdbExportOptions big;
  big.voxelSize = 10;  // no centre inside [0.001, 1]
  const auto shifted = linearField(core::makeBoxMesh(1, 1, 1, Vec3(0.001, 0, 0), Vec3(1, 1, 1)));
  EXPECT_THROW(io::writeFieldVdb(path, shifted, big), core::Error);
  io::VdbExportOptions none;
  none.voxelSize = 0.1;
  none.quantities.tensor = false;
  EXPECT_THROW(io::writeFieldVdb(path, field, none), core::Error);
  EXPECT_TRUE(dir.entries().empty());

  { std::ofstream(dir.path() / "file") << "x"; }
  io::VdbExportOptions ok;
  ok.voxelSize = 0.25;
  EXPECT_THROW(io::writeFieldVdb(dir.path() / "file" / "sub" / "f.vdb", field, ok), core::Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});
  EXPECT_THROW(io::readVdbFile(dir.path() / "file"), core::Error);
  EXPECT_THROW(io::readVdbFile(dir.path() / "missing.vdb"), core::Error);
}

TEST(VdbWriter, CancelledExportLeavesNoFileAndKeepsTheOldOne) {
  TempDir dir("cancel");
  const auto field = linearField(core::makeBoxMesh(4, 4, 4, Vec3(0, 0, 0), Vec3(1, 1, 1)));
  const fs::path path = dir.path() / "c.vdb";
  io::VdbExportOptions o;
  o.voxelSize = 0.05;
  io::writeFieldVdb(path, field, o);
  const auto size = fs::file_size(path);
  std::atomic<bool> cancel{false};
  int reports = 0;
  const core::Progress progress(
      [&](double, std::string_view) {
        if (++reports == 2) cancel = true;  // during the second layer of leaf blocks
      },
      &cancel);
  o.voxelSize = 0.02;
  EXPECT_THROW(io::writeFieldVdb(path, field, o, progress), core::Cancelled);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.vdb"});
  EXPECT_EQ(fs::file_size(path), size);
  EXPECT_EQ(io::readVdbFile(path).grids.front().voxelSize, Vec3::Constant(0.05));
}

TEST(VdbWriter, GridsAreBitwiseIdenticalForOneAndTwoThreads) {
  TempDir dir("threads");
  const auto field = linearField(test::carvedBall(10, Vec3(0, 0, 0), 1.0));
  auto options = allQuantities(field, 0.04);
  std::vector<io::VdbFileData> files;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const fs::path path = dir.path() / ("t" + std::to_string(threads) + ".vdb");
    io::writeFieldVdb(path, field, options);
    files.push_back(io::readVdbFile(path));
  }
  ASSERT_EQ(files[0].grids.size(), files[1].grids.size());
  for (std::size_t g = 0; g < files[0].grids.size(); ++g) {
    const auto& a = files[0].grids[g];
    const auto& b = files[1].grids[g];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.metadata, b.metadata);
    ASSERT_EQ(a.activeVoxels.size(), b.activeVoxels.size());
    EXPECT_GT(a.activeVoxels.size(), 20000u);
    for (std::size_t i = 0; i < a.activeVoxels.size(); ++i) {
      ASSERT_EQ(a.activeVoxels[i].ijk, b.activeVoxels[i].ijk);
      ASSERT_EQ(std::memcmp(a.activeVoxels[i].value.data(), b.activeVoxels[i].value.data(),
                            sizeof(double) * 3),
                0);
    }
  }
}

}  // namespace
}  // namespace tfd
