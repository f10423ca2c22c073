// Surface readers reject bad files with a message naming the file, the place and the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "io/binary_io.h"
#include "io/mesh/surface_readers.h"
#include "io/mesh/surface_writers.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;

class SurfaceErrors : public testing::Test {
 protected:
  void SetUp() override {
    // Unique per process and test: several build trees may run the suite at once.
    dir_ =
        fs::temp_directory_path() / ("tfd_surface_errors_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes `bytes` to `name`, reads it with `reader`, returns the error message.
  template <class Reader>
  std::string error(const std::string& name, const std::string& bytes, Reader reader) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    try {
      reader(p);
    } catch (const core::Error& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

std::string offHeader(int nv, int nf) {
  return "OFF\n" + std::to_string(nv) + " " + std::to_string(nf) + " 0\n";
}

TEST_F(SurfaceErrors, TruncatedOffSaysHowManyWereExpectedAndFound) {
  std::string text = offHeader(120, 10);
  for (int i = 0; i < 37; ++i) text += "0 0 " + std::to_string(i) + "\n";
  // 2 header lines + 37 vertex lines + a trailing comment line = 40 lines.
  text += "# cut here\n";
  EXPECT_EQ(
      error("x.off", text, readOff),
      "file '" + path("x.off") + "': expected 120 vertices, found 37 (file ended at line 40)");
  // Truncated inside the faces.
  text = offHeader(3, 2) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(error("y.off", text, readOff),
            "file '" + path("y.off") + "': expected 2 faces, found 1 (file ended at line 6)");
}

TEST_F(SurfaceErrors, OffBadNumbersIndicesAndEmptyMeshes) {
  std::string m = error("a.off", offHeader(3, 1) + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", readOff);
  EXPECT_EQ(m, "file '" + path("a.off") +
                   "', line 4: expected coordinate z of vertex 1 (a finite number), found 'zero'");
  m = error("b.off", offHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", readOff);
  EXPECT_EQ(m, "file '" + path("b.off") + "', line 6: face 0 uses vertex 3, out of range [0, 3)");
  m = error("c.off", offHeader(3, 0) + "0 0 0\n1 0 0\n0 1 0\n", readOff);
  EXPECT_NE(m.find("no faces"), std::string::npos) << m;
  m = error("d.off", "OFF\n", readOff);
  EXPECT_NE(m.find("expected the counts"), std::string::npos) << m;
  m = error("e.off", "PLY\n", readOff);
  EXPECT_NE(m.find("line 1: expected the header 'OFF', found 'PLY'"), std::string::npos) << m;
  m = error("f.off", offHeader(3, 1) + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", readOff);
  EXPECT_NE(m.find("face 0 has 2 vertices"), std::string::npos) << m;
  m = error("g.off", offHeader(3, 1) + "0 0 0\n1 0 0 7\n0 1 0\n3 0 1 2\n", readOff);
  EXPECT_NE(m.find("line 4: unexpected '7' after the 3 coordinates of vertex 1"), std::string::npos)
      << m;
  m = error("h.off", offHeader(3, 1) + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", readOff);
  EXPECT_NE(m.find("finite number"), std::string::npos) << m;
}

// Found by fuzz_read_ply: element and property names were echoed raw in messages.
TEST_F(SurfaceErrors, PlyNamesAreQuotedPrintably) {
  const std::string m = error("n.ply", "ply\nformat ascii 1.0\nelement v\x1b\x07 x\n", io::readPly);
  EXPECT_NE(m.find("element 'v\\x1b\\x07'"), std::string::npos) << m;
  for (unsigned char c : m) EXPECT_GE(c, 0x20) << m;
}

TEST_F(SurfaceErrors, MissingFileIsNamed) {
  try {
    readOff(dir_ / "missing.off");
    FAIL();
  } catch (const core::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot open file '" + path("missing.off") + "': No such file or directory");
  }
}

TEST_F(SurfaceErrors, ObjIndexProblems) {
  std::string m = error("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", readObj);
  EXPECT_EQ(m, "file '" + path("a.obj") +
                   "', line 4: face uses vertex 4 but 3 vertices are defined so far");
  m = error("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", readObj);
  EXPECT_NE(m.find("line 4: vertex index 0 is invalid"), std::string::npos) << m;
  m = error("c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n", readObj);
  EXPECT_NE(m.find("face uses vertex -4"), std::string::npos) << m;
  m = error("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", readObj);
  EXPECT_NE(m.find("texture/normal indices in '1/x'"), std::string::npos) << m;
  m = error("e.obj", "v 0 0\n", readObj);
  EXPECT_NE(m.find("line 1: expected coordinate z of vertex 1"), std::string::npos) << m;
  m = error("f.obj", "v 0 0 0\n# only vertices\n", readObj);
  EXPECT_NE(m.find("no faces"), std::string::npos) << m;
}

TEST_F(SurfaceErrors, PlyHeaderAndTruncation) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string body;
  for (int i = 0; i < 7; ++i) appendScalar<float>(body, 1.0f, Endian::Little);  // 2⅓ vertices
  std::string m = error("a.ply", header + body, readPly);
  EXPECT_EQ(m, "file '" + path("a.ply") +
                   "': expected 3 vertex records, found 2 (file ended at byte " +
                   std::to_string(header.size() + body.size()) + ")");
  m = error("b.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", readPly);
  EXPECT_NE(m.find("no 'end_header'"), std::string::npos) << m;
  m = error("c.ply", "ply\nformat ascii 2.0\n", readPly);
  EXPECT_NE(m.find("line 2: expected PLY version 1.0"), std::string::npos) << m;
  m = error("d.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "end_header\n0 0\n",
            readPly);
  EXPECT_NE(m.find("no 'vertex' element with properties x, y, z"), std::string::npos) << m;
  m = error("e.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
            readPly);
  EXPECT_NE(m.find("line 13: face 0 uses vertex 9, out of range [0, 3)"), std::string::npos) << m;
  m = error("f.ply", "solid\n", readPly);
  EXPECT_NE(m.find("not a PLY file"), std::string::npos) << m;
}

TEST_F(SurfaceErrors, StlTruncation) {
  std::string b(80, ' ');
  appendScalar<std::uint32_t>(b, 2, Endian::Little);
  b += std::string(60, '\0');  // 1.2 triangles
  std::string m = error("a.stl", b, readStl);
  EXPECT_NE(m.find("binary STL header says 2 triangles (184 bytes) but the file has 144 bytes"),
            std::string::npos)
      << m;
  m = error("b.stl",
            "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n",
            readStl);
  EXPECT_EQ(m, "file '" + path("b.stl") +
                   "': expected 'vertex' (corner 3 of facet 0) (file ended at line 5)");
  m = error("c.stl", "solid x\nendsolid x\n", readStl);
  EXPECT_NE(m.find("no (non-degenerate) triangles"), std::string::npos) << m;
}

}  // namespace
}  // namespace tfd::io
