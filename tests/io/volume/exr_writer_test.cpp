// OpenEXR slice export: files are read back with the OpenEXR library (io/exr_reader) and
// checked for names, channels, slice geometry and values against analytic fields.
#include "io/volume/exr_writer.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "io/volume/exr_reader.h"
#include "tests/support/carved_ball.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;
using core::Tensor;
using core::Vec3;

/// Folder names get a per-file prefix so tests running in parallel never share one.
class TempDir : public test::TempDir {
 public:
  explicit TempDir(const std::string& name) : test::TempDir("exr-" + name) {}
};

Tensor linearTensor(const Vec3& p) {
  return Tensor{2.5 - 0.5 * p.x(), 0.5 + 0.3 * p.y(),   -1.5 + 0.2 * p.z(),
                0.3 * p.y(),       -0.25 + 0.1 * p.x(), 0.2 * p.z() - 0.05 * p.y()};
}

core::TensorField linearField(std::shared_ptr<const core::TetMesh> mesh) {
  std::vector<Tensor> values;
  for (const auto& p : mesh->positions()) values.push_back(linearTensor(p));
  return core::TensorField(std::move(mesh), std::move(values));
}

io::ExrExportOptions allQuantities(const core::TensorField& field, double voxelSize) {
  io::ExrExportOptions o;
  o.voxelSize = voxelSize;
  std::vector<double> density;
  for (const auto& p : field.mesh().positions()) density.push_back(p.x() + 2 * p.y() - p.z());
  o.quantities =
      io::VoxelQuantities{true, true, true, io::interpolateVertexScalars(field.meshPtr(), density)};
  return o;
}

Vec3 attrVec3(const io::ExrImage& image, const std::string& name) {
  const auto& a = image.attributes.at(name);
  EXPECT_EQ(a.type, "v3d") << name;
  return Vec3(a.numbers.at(0), a.numbers.at(1), a.numbers.at(2));
}
double attrNumber(const io::ExrImage& image, const std::string& name) {
  return image.attributes.at(name).numbers.at(0);
}

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ExrWriter, FramePatterns) {
  EXPECT_EQ(io::expandFramePattern("out/slice.%04d.exr", 7), "out/slice.0007.exr");
  EXPECT_EQ(io::expandFramePattern("slice.###.exr", 12), "slice.012.exr");
  EXPECT_EQ(io::expandFramePattern("s#.exr", 123), "s123.exr");
  EXPECT_EQ(io::expandFramePattern("s_%d.exr", 5), "s_5.exr");
  EXPECT_EQ(io::expandFramePattern("100%%_%02d.exr", 3), "100%_03.exr");
  EXPECT_EQ(io::expandFramePattern("a.%03d.exr", -2), "a.-02.exr");
  for (const char* bad : {"slice.exr", "a.%04d.##.exr", "a.%s.exr", "a.%04", "%d%d"}) {
    EXPECT_THROW(io::expandFramePattern(bad, 1), core::Error) << bad;
  }
}

TEST(ExrWriter, BoxSlicesHoldChannelsGeometryAndAnalyticValues) {
  TempDir dir("box");
  const auto field = linearField(core::makeBoxMesh(4, 2, 3, Vec3(0, 0, 0), Vec3(1, 0.5, 0.3)));
  auto options = allQuantities(field, 0.1);
  options.source = "exr_writer_test";
  const std::string pattern = (dir.path() / "sub" / "slice.%04d.exr").string();
  const auto stats = io::writeFieldExrSlices(pattern, field, options);
  // Centres x 0 … 1 (11), y 0 … 0.5 (6), z 0 … 0.3 (4); all inside.
  ASSERT_EQ(stats.lattice.dims(), (std::array<int, 3>{11, 6, 4}));
  EXPECT_EQ(stats.activeVoxels, 11u * 6u * 4u);
  EXPECT_EQ(stats.filesWritten, 4);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir.path() / "sub"))
    files.push_back(e.path().filename());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"slice.0000.exr", "slice.0001.exr", "slice.0002.exr",
                                             "slice.0003.exr"}));
  std::vector<fs::path> expectedFiles;  // the stats list the slices bottom to top
  for (const std::string& name : files) expectedFiles.push_back(dir.path() / "sub" / name);
  EXPECT_EQ(stats.files, expectedFiles);

  std::vector<std::string> expectedChannels = {
      "A",      "T.e1.x", "T.e1.y", "T.e1.z",     "T.e2.x",     "T.e2.y",     "T.e2.z",
      "T.e3.x", "T.e3.y", "T.e3.z", "T.eigval.x", "T.eigval.y", "T.eigval.z", "T.xx",
      "T.xy",   "T.xz",   "T.yy",   "T.yz",       "T.zz",       "density"};
  std::sort(expectedChannels.begin(), expectedChannels.end());
  for (int s = 0; s < 4; ++s) {
    SCOPED_TRACE(s);
    const io::ExrImage image = io::readExrImage(io::expandFramePattern(pattern, s));
    ASSERT_EQ(image.width, 11);
    ASSERT_EQ(image.height, 6);
    std::vector<std::string> channels;
    for (const auto& [name, type] : image.channelTypes) {
      channels.push_back(name);
      EXPECT_EQ(type, "float") << name;
    }
    EXPECT_EQ(channels, expectedChannels);
    EXPECT_EQ(image.attributes.at("compression").text, "zip");
    EXPECT_DOUBLE_EQ(attrNumber(image, "tfd.voxelSize"), 0.1);
    EXPECT_EQ(image.attributes.at("tfd.axis").text, "z");
    EXPECT_EQ(attrNumber(image, "tfd.sliceIndex"), s);
    EXPECT_EQ(attrNumber(image, "tfd.frame"), s);
    EXPECT_EQ(attrNumber(image, "tfd.sliceCount"), 4);
    EXPECT_NEAR(attrNumber(image, "tfd.z"), 0.1 * s, 1e-15);
    EXPECT_EQ(image.attributes.at("tfd.tensorComponents").text, "xx,yy,zz,xy,yz,xz");
    EXPECT_EQ(image.attributes.at("tfd.generator").text, "tfd");
    EXPECT_EQ(image.attributes.at("tfd.source").text, "exr_writer_test");
    EXPECT_EQ(image.attributes.at("tfd.indexMax").numbers, (std::vector<double>{10, 5, 3}));
    const Vec3 first = attrVec3(image, "tfd.firstPixel");
    const Vec3 colStep = attrVec3(image, "tfd.columnStep");
    const Vec3 rowStep = attrVec3(image, "tfd.rowStep");
    EXPECT_TRUE(first.isApprox(Vec3(0, 0.5, 0.1 * s), 1e-14)) << first.transpose();
    EXPECT_EQ(colStep, Vec3(0.1, 0, 0));
    EXPECT_EQ(rowStep, Vec3(0, -0.1, 0));
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 11; ++c) {
        // Row 0 is the top of the image, at the largest y.
        const Vec3 p(0.1 * c, 0.1 * (5 - r), 0.1 * s);
        EXPECT_TRUE(p.isApprox(first + c * colStep + r * rowStep, 1e-12) || p.norm() < 1e-12);
        const Tensor t = linearTensor(p);
        const auto comps = t.components();
        const char* names[6] = {"T.xx", "T.yy", "T.zz", "T.xy", "T.yz", "T.xz"};
        for (int k = 0; k < 6; ++k) ASSERT_NEAR(image.at(names[k], c, r), comps[k], 1e-6);
        const auto e = core::eigenDecompose(t);
        ASSERT_NEAR(image.at("T.eigval.x", c, r), e.values[0], 1e-6);
        ASSERT_NEAR(image.at("T.eigval.y", c, r), e.values[1], 1e-6);
        ASSERT_NEAR(image.at("T.eigval.z", c, r), e.values[2], 1e-6);
        for (int i = 0; i < 3; ++i) {
          const std::string base = "T.e" + std::to_string(i + 1);
          const Vec3 v(image.at(base + ".x", c, r), image.at(base + ".y", c, r),
                       image.at(base + ".z", c, r));
          ASSERT_NEAR(std::abs(v.dot(e.vectors.col(i))), 1.0, 1e-5);
        }
        ASSERT_NEAR(image.at("density", c, r), p.x() + 2 * p.y() - p.z(), 1e-6);
        ASSERT_EQ(image.at("A", c, r), 1.0f);
      }
  }
}

TEST(ExrWriter, PixelsOutsideACurvedVolumeAreZero) {
  TempDir dir("ball");
  const Vec3 centre(0.05, 0.0, -0.1);
  const auto field = linearField(test::carvedBall(8, centre, 1.0));
  io::ExrExportOptions options;
  options.voxelSize = 0.125;
  options.origin = Vec3(0.011, 0.023, 0.037);
  options.firstFrame = 1;
  const std::string pattern = (dir.path() / "ball_####.exr").string();
  const auto stats = io::writeFieldExrSlices(pattern, field, options);
  const auto& L = stats.lattice;
  EXPECT_EQ(stats.filesWritten, L.dims()[2]);
  EXPECT_TRUE(fs::exists(dir.path() / "ball_0001.exr"));
  EXPECT_FALSE(fs::exists(dir.path() / "ball_0000.exr"));
  const double slack = 0.25 * std::sqrt(3.0);  // carving cube diagonal
  std::size_t inside = 0, outside = 0;
  for (int s = 0; s < L.dims()[2]; ++s) {
    const io::ExrImage image = io::readExrImage(io::expandFramePattern(pattern, s + 1));
    EXPECT_EQ(image.channelTypes.size(), 7u);  // six components and A
    for (int r = 0; r < image.height; ++r)
      for (int c = 0; c < image.width; ++c) {
        const Vec3 p = L.centre(L.min[0] + c, L.max[1] - r, L.min[2] + s);
        const double d = (p - centre).norm();
        const float a = image.at("A", c, r);
        ASSERT_TRUE(a == 0.0f || a == 1.0f);
        if (d < 1.0 - slack) {
          ASSERT_EQ(a, 1.0f) << p.transpose();
        }
        if (d > 1.0 + slack) {
          ASSERT_EQ(a, 0.0f) << p.transpose();
        }
        for (const char* ch : {"T.xx", "T.yy", "T.zz", "T.xy", "T.yz", "T.xz"}) {
          if (a == 0.0f) {
            ASSERT_EQ(image.at(ch, c, r), 0.0f);
          }
        }
        if (a == 1.0f) {
          ASSERT_NEAR(image.at("T.xx", c, r), linearTensor(p).xx, 1e-6);
          ++inside;
        } else {
          ++outside;
        }
      }
  }
  EXPECT_EQ(inside, stats.activeVoxels);
  EXPECT_GT(inside, 1000u);
  EXPECT_GT(outside, 1000u);
}

TEST(ExrWriter, FailedOrCancelledExportLeavesNoNewSlice) {
  TempDir dir("fail");
  const auto field = linearField(core::makeBoxMesh(2, 2, 4, Vec3(0, 0, 0), Vec3(1, 1, 1)));
  io::ExrExportOptions options;
  options.voxelSize = 0.2;  // 6 slices
  const std::string pattern = (dir.path() / "s.%02d.exr").string();

  // Slice 2's name is taken by a folder: moving it into place fails after 0 and 1 succeeded.
  fs::create_directory(dir.path() / "s.02.exr");
  EXPECT_THROW(io::writeFieldExrSlices(pattern, field, options), core::Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.02.exr"});
  fs::remove(dir.path() / "s.02.exr");

  std::atomic<bool> cancel{false};
  int reports = 0;
  const core::Progress progress(
      [&](double, std::string_view) {
        if (++reports == 4) cancel = true;
      },
      &cancel);
  EXPECT_THROW(io::writeFieldExrSlices(pattern, field, options, progress), core::Cancelled);
  EXPECT_TRUE(dir.entries().empty());

  for (double size : {0.0, -1.0, std::nan("")}) {
    io::ExrExportOptions bad = options;
    bad.voxelSize = size;
    try {
      io::writeFieldExrSlices(pattern, field, bad);
      FAIL() << "voxel size " << size << " accepted";
    } catch (const core::Error& e) {
      EXPECT_NE(std::string(e.what()).find("voxel size"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(io::writeFieldExrSlices((dir.path() / "noframe.exr").string(), field, options),
               core::Error);
  { std::ofstream(dir.path() / "file") << "x"; }
  EXPECT_THROW(io::writeFieldExrSlices((dir.path() / "file" / "s.%d.exr").string(), field, options),
               core::Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});
  EXPECT_THROW(io::readExrImage(dir.path() / "file"), core::Error);

  // A complete export still works afterwards.
  io::writeFieldExrSlices(pattern, field, options);
  EXPECT_EQ(dir.entries().size(), 7u);
}

TEST(ExrWriter, SlicesAreByteIdenticalForOneAndTwoThreads) {
  TempDir dir("threads");
  const auto field = linearField(test::carvedBall(10, Vec3(0, 0, 0), 1.0));
  auto options = allQuantities(field, 0.05);
  int slices = 0;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    slices =
        io::writeFieldExrSlices(
            (dir.path() / ("t" + std::to_string(threads) + ".%03d.exr")).string(), field, options)
            .filesWritten;
  }
  EXPECT_GT(slices, 30);
  for (int s = 0; s < slices; ++s) {
    const std::string a =
        readBytes(io::expandFramePattern((dir.path() / "t1.%03d.exr").string(), s));
    ASSERT_FALSE(a.empty());
    ASSERT_EQ(a, readBytes(io::expandFramePattern((dir.path() / "t2.%03d.exr").string(), s))) << s;
  }
  EXPECT_EQ(dir.entries().size(), 2u * slices);
}

TEST(ExrWriter, ReExportWithFewerSlicesRemovesTheOldExtraSlicesOfItsPattern) {
  TempDir dir("owns");
  const auto field = linearField(test::carvedBall(6, Vec3(0, 0, 0), 1.0));
  io::ExrExportOptions options;
  options.voxelSize = 0.1;
  const std::string pattern = (dir.path() / "f.%03d.exr").string();
  const int fine = io::writeFieldExrSlices(pattern, field, options).filesWritten;
  // Files that only look alike stay: other names, other padding, other patterns.
  for (const char* other : {"f.5.exr", "f.0001.exr", "g.001.exr", "f.001.exr.txt"})
    std::ofstream(dir.path() / other) << "not ours";
  // A staged slice of a killed export (its process is gone) is removed too.
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  std::ofstream(dir.path() / (".f.007.tfd-tmp" + std::to_string(dead) + "-4.exr")) << "partial";
  options.voxelSize = 0.25;
  const int coarse = io::writeFieldExrSlices(pattern, field, options).filesWritten;
  ASSERT_LT(coarse, fine);
  std::vector<std::string> expected{"f.0001.exr", "f.001.exr.txt", "f.5.exr", "g.001.exr"};
  for (int s = 0; s < coarse; ++s)
    expected.push_back(fs::path(io::expandFramePattern(pattern, s)).filename());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(dir.entries(), expected);
  for (int s = 0; s < coarse; ++s) {
    const io::ExrImage image = io::readExrImage(io::expandFramePattern(pattern, s));
    EXPECT_EQ(attrNumber(image, "tfd.sliceCount"), coarse);
  }
}

TEST(ExrWriter, FrameOfFileNameAcceptsExactlyWhatThePatternWrites) {
  EXPECT_EQ(io::frameOfFileName("out/f.%03d.exr", "f.012.exr"), 12);
  EXPECT_EQ(io::frameOfFileName("f.%03d.exr", "f.1234.exr"), 1234);
  EXPECT_EQ(io::frameOfFileName("f.%03d.exr", "f.-02.exr"), -2);
  EXPECT_EQ(io::frameOfFileName("s####.exr", "s0007.exr"), 7);
  EXPECT_FALSE(io::frameOfFileName("f.%03d.exr", "f.12.exr"));
  EXPECT_FALSE(io::frameOfFileName("f.%03d.exr", "f.0012.exr"));
  EXPECT_FALSE(io::frameOfFileName("f.%d.exr", "f.x.exr"));
  EXPECT_FALSE(io::frameOfFileName("f.%d.exr", "f..exr"));
  EXPECT_TRUE(io::framePlaceholderInFileName("a/b/f.%d.exr"));
  EXPECT_FALSE(io::framePlaceholderInFileName("a/%d/f.exr"));
}

}  // namespace
}  // namespace tfd
