// Tet mesh readers reject bad files with a message naming the file, the place and the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "io/mesh/gmsh.h"
#include "io/tetgen/node_ele.h"
#include "io/vtk/vtu_reader.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;

class TetMeshErrors : public testing::Test {
 protected:
  void SetUp() override {
    // Unique per process and test: several build trees may run the suite at once.
    dir_ =
        fs::temp_directory_path() / ("tfd_tet_mesh_errors_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  template <class Fn>
  static std::string error(Fn&& fn) {
    try {
      fn();
    } catch (const core::Error& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

// Five points: two tets sharing the face (1, 2, 3).
const char* kNode = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";

TEST_F(TetMeshErrors, InvertedTetInTetgenFilesIsNamed) {
  file("m.node", kNode);
  file("m.ele", "2 4 0\n1 1 2 3 4\n2 2 3 5 4\n");  // the second is inverted
  const std::string m = error([&] { readTetgen(dir_ / "m.node"); });
  EXPECT_NE(m.find("file '" + path("m.ele") + "': invalid tet mesh"), std::string::npos) << m;
  EXPECT_NE(m.find("tet 1 is inverted"), std::string::npos) << m;
}

TEST_F(TetMeshErrors, InvertedTetInGmshIsNamed) {
  const auto p = file("m.msh",
                      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n"
                      "3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n$Elements\n2\n"
                      "1 4 0 2 1 3 4\n2 4 0 2 3 4 5\n$EndElements\n");
  const std::string m = error([&] { readGmsh(p); });
  EXPECT_NE(m.find("file '" + path("m.msh") + "'"), std::string::npos) << m;
  EXPECT_NE(m.find("tet 0 is inverted"), std::string::npos) << m;
}

TEST_F(TetMeshErrors, TruncatedAndMissingTetgenFiles) {
  file("t.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n");
  file("t.ele", "1 4 0\n1 1 2 3 4\n");
  EXPECT_EQ(error([&] { readTetgen(dir_ / "t"); }),
            "file '" + path("t.node") + "': expected 5 points, found 3 (file ended at line 4)");
  file("u.node", kNode);
  EXPECT_EQ(error([&] { readTetgen(dir_ / "u.node"); }),
            "cannot open file '" + path("u.ele") + "': No such file or directory");
  file("v.node", kNode);
  file("v.ele", "1 4 0\n1 1 2 3 6\n");
  EXPECT_EQ(error([&] { readTetgen(dir_ / "v"); }),
            "file '" + path("v.ele") + "', line 2: tet 0 uses point 6, out of range [1, 6)");
  file("w.node", "5 3 0 0\n1 0 0 0\n3 1 0 0\n");
  EXPECT_NE(error([&] { readTetgen(dir_ / "w"); }).find("line 3: expected point number 2, found 3"),
            std::string::npos);
  file("x.node", "5 2 0 0\n");
  EXPECT_NE(error([&] { readTetgen(dir_ / "x"); }).find("the dimension must be 3"),
            std::string::npos);
}

TEST_F(TetMeshErrors, GmshProblems) {
  const std::string format2 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  std::string m = error([&] {
    readGmsh(file("a.msh", format2 + "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"));
  });
  EXPECT_EQ(m,
            "file '" + path("a.msh") + "', line 9: expected 5 nodes, found 3 before '$EndNodes'");
  m = error([&] { readGmsh(file("b.msh", format2 + "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n")); });
  EXPECT_EQ(m, "file '" + path("b.msh") + "': expected 5 nodes, found 3 (file ended at line 8)");
  m = error([&] { readGmsh(file("c.msh", "$MeshFormat\n2.2 1 8\n$EndMeshFormat\n")); });
  EXPECT_NE(m.find("binary .msh files are not supported"), std::string::npos) << m;
  m = error([&] {
    readGmsh(file("d.msh", format2 +
                               "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n"
                               "7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n1\n"
                               "1 5 0 1 2 3 4 5 6 7 8\n$EndElements\n"));
  });
  EXPECT_NE(m.find("line 17: element 1 is a hexahedron (type 5); only tetrahedra are supported"),
            std::string::npos)
      << m;
  m = error([&] {
    readGmsh(file("e.msh", format2 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                                     "$Elements\n1\n1 4 0 1 2 3 7\n$EndElements\n"));
  });
  EXPECT_NE(m.find("element 1 uses node 7, which is not defined"), std::string::npos) << m;
  m = error([&] {
    readGmsh(file("f.msh", format2 + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                                     "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n"));
  });
  EXPECT_NE(m.find("no tetrahedra in the mesh (only lower-dimensional elements)"),
            std::string::npos)
      << m;
  m = error([&] { readGmsh(file("g.msh", "$Nodes\n1\n1 0 0 0\n$EndNodes\n")); });
  EXPECT_NE(m.find("expected '$MeshFormat' first"), std::string::npos) << m;
  m = error([&] { readGmsh(file("h.msh", format2 + "$Nodes\n1\n1 0 0 zero\n$EndNodes\n")); });
  EXPECT_NE(m.find("line 6: expected coordinate z of node 1 (a finite number), found 'zero'"),
            std::string::npos)
      << m;
}

// Found by fuzz_read_gmsh: an unknown section's name was echoed raw in "expected '$End...'".
TEST_F(TetMeshErrors, GmshSectionNamesAreQuotedPrintably) {
  const std::string m = error([&] {
    readGmsh(file("s.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Odd\x1b\x07\n1 2\n"));
  });
  EXPECT_EQ(m, "file '" + path("s.msh") + "': expected '$EndOdd\\x1b\\x07' (file ended at line 5)");
}

// Found by fuzz_read_gmsh in CI: a section end line with binary bytes was quoted raw in
// "expected 4 node coordinates, found 1 before '$EndNode...'".
TEST_F(TetMeshErrors, GmshTruncatedSectionQuotesItsEndLinePrintably) {
  const std::string m = error([&] {
    readGmsh(file("t.msh",
                  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n"
                  "$EndNode\xff\x01s\n"));
  });
  EXPECT_NE(m.find("found 1 before '$EndNode\\xff\\x01s'"), std::string::npos) << m;
  EXPECT_EQ(m.find('\x01'), std::string::npos) << m;
}

// Found by CI's fuzz run: a v4.1 node block announcing -14 nodes made the reader size a vector
// with it (std::length_error, not our error); a block may hold only what the header has left.
TEST_F(TetMeshErrors, GmshBlockCountsMustFitTheHeader) {
  const std::string format4 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  std::string m = error(
      [&] { readGmsh(file("n.msh", format4 + "$Nodes\n1 4 1 4\n3 1 0 -14\n1\n2\n$EndNodes\n")); });
  EXPECT_NE(m.find("a block announces -14 nodes, but the header leaves 4"), std::string::npos) << m;
  m = error(
      [&] { readGmsh(file("m.msh", format4 + "$Nodes\n1 4 1 4\n3 1 0 9\n1\n2\n$EndNodes\n")); });
  EXPECT_NE(m.find("a block announces 9 nodes, but the header leaves 4"), std::string::npos) << m;
  m = error([&] {
    readGmsh(file("e.msh", format4 + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n"
                                     "0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 -2\n"));
  });
  EXPECT_NE(m.find("a block announces -2 elements, but the header leaves 1"), std::string::npos)
      << m;
}

// Found by a local fuzz run: the VTU's XML parser quoted an unknown entity raw, control bytes
// and line breaks included; its messages are now printable like every other reader's.
TEST_F(TetMeshErrors, VtuXmlMessagesArePrintable) {
  const std::string m = error([&] {
    readVtu(file("x.vtu", "<VTKFile type=\"UnstructuredGrid\">&a\x01\nb\x1c;</VTKFile>\n"));
  });
  EXPECT_NE(m.find("unknown entity '&a\\x01\\x0ab\\x1c;'"), std::string::npos) << m;
  for (unsigned char c : m) EXPECT_FALSE(c < 0x20 || c == 0x7f) << m;
}

TEST_F(TetMeshErrors, VtuProblems) {
  auto vtu = [](const std::string& types, const std::string& extraRoot = "") {
    return "<VTKFile type=\"UnstructuredGrid\"" + extraRoot +
           "><UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n"
           "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
           "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Cells>\n"
           "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
           "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" +
           types + "</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n";
  };
  EXPECT_EQ(error([&] { readVtu(file("ok.vtu", vtu("10"))); }), "(no error)");
  std::string m = error([&] { readVtu(file("a.vtu", vtu("12"))); });
  EXPECT_NE(m.find("line 3: cell 0 has VTK type 12 (not a tetrahedron)"), std::string::npos) << m;
  m = error([&] { readVtu(file("b.vtu", vtu("10", " compressor=\"vtkLZ4DataCompressor\""))); });
  EXPECT_NE(m.find("compressor \"vtkLZ4DataCompressor\" is not supported"), std::string::npos) << m;
  m = error([&] { readVtu(file("c.vtu", vtu("10").substr(0, vtu("10").find("</Cells>")))); });
  EXPECT_NE(m.find("the file ended inside <"), std::string::npos) << m;
  m = error([&] { readVtu(file("d.vtu", "<VTKFile type=\"PolyData\"></VTKFile>")); });
  EXPECT_NE(m.find("expected a VTKFile of type \"UnstructuredGrid\", found \"PolyData\""),
            std::string::npos)
      << m;
  // Appended raw data cut short.
  m = error([&] {
    readVtu(file("e.vtu",
                 "<VTKFile type=\"UnstructuredGrid\" header_type=\"UInt64\"><UnstructuredGrid>"
                 "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>"
                 "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
                 "offset=\"0\"/></Points></Piece></UnstructuredGrid>"
                 "<AppendedData encoding=\"raw\">_" +
                     std::string("\x60\0\0\0\0\0\0\0abc", 11)));
  });
  EXPECT_NE(m.find("binary data ends early: needs 96 bytes"), std::string::npos) << m;
}

// Found by fuzz_read_vtu: attribute values (here a DataArray format) were echoed raw.
TEST_F(TetMeshErrors, VtuAttributeValuesAreQuotedPrintably) {
  const std::string m = error([&] {
    readVtu(file("f.vtu",
                 "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
                 "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>"
                 "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"asc\x1bi\">"
                 "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points></Piece></UnstructuredGrid>"
                 "</VTKFile>\n"));
  });
  EXPECT_NE(m.find("unknown DataArray format \"asc\\x1bi\""), std::string::npos) << m;
  EXPECT_EQ(m.find('\x1b'), std::string::npos) << m;
}

TEST_F(TetMeshErrors, FailedWriteLeavesNoFile) {
  const auto mesh = core::makeBoxMesh(1, 1, 1, core::Vec3(0, 0, 0), core::Vec3(1, 1, 1));
  file("blocker", "a regular file where a folder should be");
  const std::string m = error([&] { writeGmsh(dir_ / "blocker" / "m.msh", *mesh); });
  EXPECT_NE(m.find("blocker"), std::string::npos) << m;
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    (void)entry;
    ++count;
  }
  EXPECT_EQ(count, 1u);
}

}  // namespace
}  // namespace tfd::io
