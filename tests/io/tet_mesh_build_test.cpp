// Tet mesh files: exact round trips through our writers, hand-written files of each format.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>

#include "core/structured_mesh.h"
#include "io/base64.h"
#include "io/binary_io.h"
#include "io/mesh/gmsh.h"
#include "io/tetgen/node_ele.h"
#include "io/tetgen/tetgen_mesher.h"
#include "io/vtk/vtu_reader.h"
#include "io/vtk/vtu_writer.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;
using core::TetMesh;
using core::Vec3;

class TetMeshIo : public testing::Test {
 protected:
  void SetUp() override {
    // Unique per process and test: several build trees may run the suite at once.
    dir_ =
        fs::temp_directory_path() / ("tfd_tet_mesh_io_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes = {}) {
    const fs::path p = dir_ / name;
    if (!bytes.empty()) std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  fs::path dir_;
};

/// An irregular TetGen mesh with coordinates that need all 17 digits.
std::shared_ptr<const TetMesh> awkwardMesh() {
  static const auto mesh = [] {
    const auto m = meshPrimitive(core::PrimitiveShape::Torus, 3000);
    std::vector<Vec3> p = m->positions();
    for (auto& x : p) x = x / 3.0 + Vec3(1e-9, -7.123456789, 1e4 / 7);
    return std::make_shared<const TetMesh>(std::move(p), m->tets());
  }();
  return mesh;
}

void expectIdentical(const TetMesh& a, const TetMesh& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.tetCount(), b.tetCount());
  for (std::size_t v = 0; v < a.vertexCount(); ++v) {
    ASSERT_EQ(a.positions()[v], b.positions()[v]) << "vertex " << v;
  }
  EXPECT_EQ(a.tets(), b.tets());
}

TEST_F(TetMeshIo, TetgenGmshAndVtuRoundTripExactly) {
  const auto m = awkwardMesh();
  writeTetgen(file("m"), *m);
  EXPECT_TRUE(fs::exists(file("m.node")) && fs::exists(file("m.ele")));
  expectIdentical(*readTetgen(file("m.ele")), *m);
  expectIdentical(*readTetgen(file("m")), *m);
  for (auto version : {GmshVersion::V2, GmshVersion::V4}) {
    writeGmsh(file("m.msh"), *m, version);
    expectIdentical(*readGmsh(file("m.msh")), *m);
  }
  for (auto encoding : {VtkEncoding::Appended, VtkEncoding::Base64, VtkEncoding::Ascii}) {
    VtuMeshOptions options;
    options.encoding = encoding;
    options.pointData.push_back({"height", 1, std::vector<double>(m->vertexCount(), 2.5)});
    writeMeshVtu(file("m.vtu"), *m, options);
    expectIdentical(*readVtu(file("m.vtu")), *m);
  }
}

TEST_F(TetMeshIo, HandWrittenTetgenFilesZeroAndOneBased) {
  // Two tets sharing a face; attributes, markers, comments; 1-based.
  file("a.node",
       "# points\n5 3 1 1\n1 0 0 0 7.5 1\n2 1 0 0 7.5 1\n3 0 1 0 7.5 1\n"
       "4 0 0 1 7.5 1\n5 1 1 1 7.5 0  # last\n");
  file("a.ele", "2 4 1\n1 1 2 3 4 10\n2 2 3 4 5 20\n");
  auto m = readTetgen(file("a.node"));
  EXPECT_EQ(m->vertexCount(), 5u);
  EXPECT_EQ(m->tetCount(), 2u);
  EXPECT_NEAR(m->totalVolume(), 1.0 / 6 + 1.0 / 3, 1e-15);
  // 0-based, 10-node tets (corners first), and one unused point which is dropped.
  file("b.node", "6 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 9 9 9\n5 0.5 0 0\n");
  file("b.ele", "1 10 0\n0 0 1 2 3 5 5 5 5 5 5\n");
  m = readTetgen(file("b"));
  EXPECT_EQ(m->vertexCount(), 4u);
  EXPECT_EQ(m->tetCount(), 1u);
}

TEST_F(TetMeshIo, ConsistentlyInvertedMeshesAreFlipped) {
  // TetGen-style files where every tet is negatively oriented.
  const auto box = core::makeBoxMesh(2, 2, 2, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::string node = std::to_string(box->vertexCount()) + " 3 0 0\n", ele;
  for (std::size_t v = 0; v < box->vertexCount(); ++v) {
    const Vec3& p = box->positions()[v];
    node += std::to_string(v) + " " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
            std::to_string(p.z()) + "\n";
  }
  ele = std::to_string(box->tetCount()) + " 4 0\n";
  for (std::size_t t = 0; t < box->tetCount(); ++t) {
    const auto& k = box->tets()[t];
    ele += std::to_string(t) + " " + std::to_string(k[0]) + " " + std::to_string(k[2]) + " " +
           std::to_string(k[1]) + " " + std::to_string(k[3]) + "\n";
  }
  file("inv.node", node);
  file("inv.ele", ele);
  const auto m = readTetgen(file("inv"));
  EXPECT_NEAR(m->totalVolume(), 1.0, 1e-12);
  for (double v : m->tetVolumes()) EXPECT_GT(v, 0);
}

TEST_F(TetMeshIo, HandWrittenGmsh2WithOtherElementsAndSparseTags) {
  const auto p = file("a.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "solid"
$EndPhysicalNames
$Nodes
5
10 0 0 0
20 1 0 0
30 0 1 0
40 0 0 1
50 1 1 1
$EndNodes
$Elements
4
1 15 2 0 1 10
2 2 2 0 1 10 20 30
3 4 2 1 1 10 20 30 40
4 4 3 1 1 0 20 30 40 50
$EndElements
)");
  const auto m = readGmsh(p);
  EXPECT_EQ(m->vertexCount(), 5u);
  ASSERT_EQ(m->tetCount(), 2u);
  EXPECT_EQ(m->tets()[1], (TetMesh::Tet{1, 2, 3, 4}));
  EXPECT_NEAR(m->totalVolume(), 1.0 / 6 + 1.0 / 3, 1e-15);
}

TEST_F(TetMeshIo, HandWrittenGmsh41EntityBlocksAnd40) {
  // Two volume entities and a surface block; node tags out of order; a parametric block.
  const auto p41 = file("a.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 1 2
1 0 0 0 1 1 0 0 0
1 0 0 0 1 1 1 0 0
2 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
2 5 1 9
3 1 0 3
9
2
1
0 0 0
1 0 0
0 1 0
2 1 1 2
4
5
0 0 1 0.25 0.5
1 1 1 0.5 0.5
$EndNodes
$Elements
3 3 1 3
2 1 2 1
7 9 2 1
3 1 4 1
1 9 2 1 4
3 2 4 1
3 2 1 4 5
$EndElements
)");
  auto m = readGmsh(p41);
  EXPECT_EQ(m->vertexCount(), 5u);
  EXPECT_EQ(m->tetCount(), 2u);
  EXPECT_NEAR(m->totalVolume(), 1.0 / 6 + 1.0 / 3, 1e-15);

  const auto p40 = file("b.msh", R"($MeshFormat
4 0 8
$EndMeshFormat
$Nodes
1 4
1 3 0 4
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
$EndNodes
$Elements
1 1
1 3 4 1
1 1 2 3 4
$EndElements
)");
  m = readGmsh(p40);
  EXPECT_EQ(m->tetCount(), 1u);
  EXPECT_NEAR(m->totalVolume(), 1.0 / 6, 1e-15);
}

TEST_F(TetMeshIo, HandWrittenVtuAsciiLikeParaView) {
  // ParaView's ASCII layout: Int64 connectivity, a triangle cell (ignored), point data.
  const auto p = file("a.vtu", R"(<?xml version="1.0"?>
<!-- saved by hand -->
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="3">
      <PointData Scalars="s">
        <DataArray type="Float32" Name="s" format="ascii">1 2 3 4 5</DataArray>
      </PointData>
      <CellData/>
      <Points>
        <DataArray type="Float32" Name="Points" NumberOfComponents="3" format="ascii" RangeMin="0" RangeMax="1.7320508076">
          0 0 0 1 0 0
          0 1 0 0 0 1
          1 1 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">
          0 1 2 0 1 2 3 1 2 3 4
        </DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3 7 11</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">5 10 10</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)");
  const auto m = readVtu(p);
  EXPECT_EQ(m->vertexCount(), 5u);
  EXPECT_EQ(m->tetCount(), 2u);
  EXPECT_NEAR(m->totalVolume(), 1.0 / 6 + 1.0 / 3, 1e-7);
}

/// A VTU with appended data as VTK writes it: UInt32 headers, optionally zlib-compressed
/// (several blocks), optionally big endian, raw or base64.
std::string vtkStyleVtu(bool zlib, Endian e, bool base64) {
  const float points[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  std::string pts, conn, offs, types;
  for (const auto& p : points) {
    for (float c : p) appendScalar<float>(pts, c, e);
  }
  for (int v : {0, 1, 2, 3, 1, 2, 3, 4}) appendScalar<std::int32_t>(conn, v, e);
  for (int o : {4, 8}) appendScalar<std::int32_t>(offs, o, e);
  types = std::string("\x0a\x0a", 2);
  std::string appended;
  std::vector<std::size_t> offsets;
  for (const std::string* block : {&pts, &conn, &offs, &types}) {
    offsets.push_back(appended.size());
    std::string bytes;
    if (zlib) {
      // Blocks of 16 uncompressed bytes, as vtkZLibDataCompressor splits them.
      const std::size_t blockSize = 16;
      const std::size_t n = (block->size() + blockSize - 1) / blockSize;
      std::string head, data;
      appendScalar<std::uint32_t>(head, std::uint32_t(n), e);
      appendScalar<std::uint32_t>(head, std::uint32_t(blockSize), e);
      appendScalar<std::uint32_t>(head, std::uint32_t(block->size() % blockSize), e);
      for (std::size_t b = 0; b < n; ++b) {
        const std::string part = block->substr(b * blockSize, blockSize);
        uLongf len = compressBound(uLong(part.size()));
        std::string out(len, '\0');
        compress2(reinterpret_cast<Bytef*>(out.data()), &len,
                  reinterpret_cast<const Bytef*>(part.data()), uLong(part.size()), 6);
        out.resize(len);
        appendScalar<std::uint32_t>(head, std::uint32_t(len), e);
        data += out;
      }
      if (base64) {
        appendBase64(bytes, head);  // VTK encodes header and data separately
        appendBase64(bytes, data);
      } else {
        bytes = head + data;
      }
    } else {
      std::string head;
      appendScalar<std::uint32_t>(head, std::uint32_t(block->size()), e);
      if (base64) {
        appendBase64(bytes, head);
        appendBase64(bytes, *block);
      } else {
        bytes = head + *block;
      }
    }
    appended += bytes;
  }
  auto arr = [&](const char* type, const char* name, int comps, int i) {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name +
           "\" NumberOfComponents=\"" + std::to_string(comps) + "\" format=\"appended\" offset=\"" +
           std::to_string(offsets[i]) + "\"/>\n";
  };
  std::string xml =
      std::string("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"") +
      (e == Endian::Little ? "LittleEndian" : "BigEndian") + "\"" +
      (zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") +
      ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">\n"
      "<Points>\n" +
      arr("Float32", "Points", 3, 0) + "</Points>\n<Cells>\n" + arr("Int32", "connectivity", 1, 1) +
      arr("Int32", "offsets", 1, 2) + arr("UInt8", "types", 1, 3) +
      "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"" +
      (base64 ? "base64" : "raw") + "\">\n   _" + appended + "\n</AppendedData>\n</VTKFile>\n";
  return xml;
}

TEST_F(TetMeshIo, HandWrittenVtuAppendedRawBase64ZlibBothEndians) {
  for (bool zlib : {false, true}) {
    for (Endian e : {Endian::Little, Endian::Big}) {
      for (bool base64 : {false, true}) {
        const auto m = readVtu(file("a.vtu", vtkStyleVtu(zlib, e, base64)));
        EXPECT_EQ(m->vertexCount(), 5u) << zlib << base64;
        ASSERT_EQ(m->tetCount(), 2u);
        EXPECT_EQ(m->tets()[1], (TetMesh::Tet{1, 2, 3, 4}));
        EXPECT_NEAR(m->totalVolume(), 1.0 / 6 + 1.0 / 3, 1e-15);
      }
    }
  }
}

}  // namespace
}  // namespace tfd::io
