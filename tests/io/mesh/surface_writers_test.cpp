// Surface readers and writers: exact round trips and hand-written files of every format.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
#include "io/binary_io.h"
#include "io/mesh/surface_readers.h"
#include "io/mesh/surface_writers.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;
using core::SurfaceMesh;
using core::Vec3;

class SurfaceIo : public testing::Test {
 protected:
  void SetUp() override {
    // Unique per process and test: several build trees may run the suite at once.
    dir_ =
        fs::temp_directory_path() / ("tfd_surface_io_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes = {}) {
    const fs::path p = dir_ / name;
    if (!bytes.empty()) {
      std::ofstream out(p, std::ios::binary);
      out << bytes;
    }
    return p;
  }
  fs::path dir_;
};

/// A mesh with awkward coordinates (not representable in short decimals).
SurfaceMesh awkwardMesh() {
  SurfaceMesh m = core::makeTorus(1.0, 0.3, 0.2);
  for (auto& p : m.positions) p = p * (1.0 / 3.0) + Vec3(1e-7, -123.456789, 1e5 / 7);
  return m;
}

void expectIdentical(const SurfaceMesh& a, const SurfaceMesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    ASSERT_EQ(a.positions[i], b.positions[i]) << "vertex " << i;
  }
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST_F(SurfaceIo, OffObjPlyRoundTripExactly) {
  const SurfaceMesh m = awkwardMesh();
  writeOff(file("m.off"), m);
  expectIdentical(readOff(file("m.off")), m);
  writeObj(file("m.obj"), m);
  expectIdentical(readObj(file("m.obj")), m);
  for (auto e :
       {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    writePly(file("m.ply"), m, e);
    expectIdentical(readPly(file("m.ply")), m);
  }
}

TEST_F(SurfaceIo, StlRoundTripsFloatGeometryAndWelds) {
  // STL stores float32: use float-exact coordinates; positions come back welded in order of
  // first appearance, which for this mesh is a renumbering we can check through geometry.
  SurfaceMesh m = core::makeSphere(1.0, 0.4);
  // Through a volatile float: GCC 12.2 -O2 wrongly folds double(float(x)) away in such loops.
  for (auto& p : m.positions) {
    for (int i = 0; i < 3; ++i) {
      volatile float f = float(p[i]);
      p[i] = f;
    }
  }
  for (bool binary : {true, false}) {
    writeStl(file("m.stl"), m, binary);
    const SurfaceMesh r = readStl(file("m.stl"));
    ASSERT_EQ(r.positions.size(), m.positions.size()) << "welded back to shared vertices";
    ASSERT_EQ(r.triangles.size(), m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(r.positions[r.triangles[t][k]], m.positions[m.triangles[t][k]]);
      }
    }
    EXPECT_TRUE(core::closedSurfaceProblems(r).empty());
    EXPECT_EQ(core::eulerCharacteristic(r), 2);
  }
}

TEST_F(SurfaceIo, HandWrittenOffWithPolygonsAndComments) {
  // A unit cube with quads: fan triangulation gives 12 triangles, outward.
  const auto p = file("cube.off", R"(OFF
# a cube
8 6 12
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5   # comment after a face
4 2 3 7 6
4 3 0 4 7 255 0 0
)");
  const SurfaceMesh m = readOff(p);
  EXPECT_EQ(m.positions.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_TRUE(core::closedSurfaceProblems(m).empty());
  EXPECT_NEAR(core::enclosedVolume(m), 1.0, 1e-15);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 3, 2}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 1}));
}

TEST_F(SurfaceIo, HandWrittenObjWithSlashFormsAndNegativeIndices) {
  const auto p = file("tet.obj",
                      "# tetrahedron\r\n"
                      "o thing\n"
                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1 1.0\n"
                      "vt 0 0\nvn 0 0 1\n"
                      "g faces\nusemtl none\ns off\n"
                      "f 1/1/1 3/1/1 2/1/1\n"
                      "f 1//1 2//1 4//1\n"
                      "f -3/1 -2/1 -1/1\n"  // 2 3 4
                      "f 1 4 3\n");
  const SurfaceMesh m = readObj(p);
  EXPECT_EQ(m.positions.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.triangles[2], (std::array<int, 3>{1, 2, 3}));
  EXPECT_TRUE(core::closedSurfaceProblems(m).empty());
  EXPECT_NEAR(core::enclosedVolume(m), 1.0 / 6.0, 1e-15);
  // A pentagon is fanned into three triangles.
  const SurfaceMesh pent =
      readObj(file("pent.obj", "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n"));
  EXPECT_EQ(pent.triangles.size(), 3u);
}

TEST_F(SurfaceIo, HandWrittenPlyAsciiWithExtraElementsAndProperties) {
  const auto p = file("tet.ply", R"(ply
format ascii 1.0
comment made by hand
element vertex 4
property float x
property float y
property float z
property uchar red
element face 2
property list uchar int vertex_indices
property int flags
element edge 1
property int vertex1
property int vertex2
end_header
0 0 0 255
1 0 0 0
0 1 0 0
0 0 1 0
3 0 2 1 7
4 0 1 3 2 0
0 1
)");
  const SurfaceMesh m = readPly(p);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.positions[3], Vec3(0, 0, 1));
}

/// Writes a binary PLY by hand: float32 xyz, an int16 extra property, uint8/uint32 lists.
std::string binaryPly(Endian e) {
  std::string s = std::string("ply\nformat ") +
                  (e == Endian::Little ? "binary_little_endian" : "binary_big_endian") +
                  " 1.0\nelement vertex 4\nproperty float x\nproperty short tag\n"
                  "property float y\nproperty float z\nelement face 1\n"
                  "property list uchar uint vertex_indices\nend_header\n";
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& p : v) {
    appendScalar<float>(s, p[0], e);
    appendScalar<std::int16_t>(s, -7, e);
    appendScalar<float>(s, p[1], e);
    appendScalar<float>(s, p[2], e);
  }
  s += char(4);
  for (std::uint32_t i : {0u, 1u, 2u, 3u}) appendScalar<std::uint32_t>(s, i, e);
  return s;
}

TEST_F(SurfaceIo, HandWrittenBinaryPlyBothEndians) {
  for (Endian e : {Endian::Little, Endian::Big}) {
    const SurfaceMesh m = readPly(file("quad.ply", binaryPly(e)));
    ASSERT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions[2], Vec3(1, 1, 0));
    EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
  }
}

TEST_F(SurfaceIo, HandWrittenStlAsciiAndBinary) {
  const auto ascii = file("tri.stl", R"(solid test
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 1 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex 1 0 0
      vertex 1 1 0
      vertex 0 1 0
    endloop
  endfacet
endsolid test
)");
  SurfaceMesh m = readStl(ascii);
  EXPECT_EQ(m.positions.size(), 4u);  // welded
  EXPECT_EQ(m.triangles.size(), 2u);

  // Binary, with a header that starts with "solid" (as many exporters write), plus a degenerate
  // triangle that welding collapses and drops.
  std::string b = "solid but binary";
  b.resize(80, ' ');
  appendScalar<std::uint32_t>(b, 3, Endian::Little);
  const float tris[3][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                               {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                               {{1, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  for (const auto& t : tris) {
    for (int i = 0; i < 3; ++i) appendScalar<float>(b, 0.0f, Endian::Little);
    for (const auto& v : t) {
      for (float c : v) appendScalar<float>(b, c, Endian::Little);
    }
    appendScalar<std::uint16_t>(b, 0, Endian::Little);
  }
  m = readStl(file("bin.stl", b));
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 2u);
}

}  // namespace
}  // namespace tfd::io
