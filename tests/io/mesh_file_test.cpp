// Format dispatch by extension and format detection.
#include "io/mesh_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/error.h"
#include "core/surface/primitives.h"
#include "io/tetgen/tetgen_mesher.h"

namespace tfd::io {
namespace {

namespace fs = std::filesystem;

class MeshFile : public testing::Test {
 protected:
  void SetUp() override {
    // Unique per process and test: several build trees may run the suite at once.
    dir_ =
        fs::temp_directory_path() / ("tfd_mesh_file_" + std::to_string(::getpid()) + "_" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(MeshFile, KindsByExtensionCaseInsensitive) {
  for (const char* name : {"a.off", "b.OBJ", "c.ply", "d.Stl"}) {
    EXPECT_TRUE(isSurfaceMeshFile(name)) << name;
    EXPECT_FALSE(isTetMeshFile(name)) << name;
  }
  for (const char* name : {"a.node", "b.ele", "c.MSH", "d.vtu"}) {
    EXPECT_TRUE(isTetMeshFile(name)) << name;
    EXPECT_FALSE(isSurfaceMeshFile(name)) << name;
  }
  EXPECT_FALSE(isTetMeshFile("mesh.vtk"));
  try {
    readTetMesh(dir_ / "mesh.vtk");
    FAIL();
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown tet mesh format '.vtk' (expected .node, .ele, "
                                         ".msh or .vtu)"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(MeshFile, EverySurfaceExtensionRoundTrips) {
  const core::SurfaceMesh sphere = core::makeSphere(1.0, 0.5);
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    const fs::path p = dir_ / (std::string("s") + ext);
    writeSurfaceMesh(p, sphere);
    const core::SurfaceMesh back = readSurfaceMesh(p);
    EXPECT_EQ(back.triangles.size(), sphere.triangles.size()) << ext;
    EXPECT_EQ(back.positions.size(), sphere.positions.size()) << ext;
  }
}

TEST_F(MeshFile, EveryTetExtensionRoundTrips) {
  const auto mesh = meshPrimitive(core::PrimitiveShape::Sphere, 2000);
  for (const char* ext : {".node", ".msh", ".vtu"}) {
    const fs::path p = dir_ / (std::string("t") + ext);
    writeTetMesh(p, *mesh);
    const auto back = readTetMesh(p);
    EXPECT_EQ(back->tets(), mesh->tets()) << ext;
    EXPECT_EQ(back->positions(), mesh->positions()) << ext;
  }
}

TEST_F(MeshFile, FormatsAreDetectedFromTheFirstBytes) {
  const fs::path ply = dir_ / "torus.ply";
  writeSurfaceMesh(ply, core::makeTorus(1.0, 0.4, 0.2));
  EXPECT_EQ(meshFileFormat(ply), "PLY (binary_little_endian)");
  const fs::path stl = dir_ / "torus.stl";
  writeSurfaceMesh(stl, core::makeTorus(1.0, 0.4, 0.2));
  EXPECT_EQ(meshFileFormat(stl), "STL (binary)");
  const fs::path msh = dir_ / "s.msh";
  writeTetMesh(msh, *meshPrimitive(core::PrimitiveShape::Sphere, 2000));
  EXPECT_EQ(meshFileFormat(msh), "Gmsh .msh 4.1 (ASCII)");
}

}  // namespace
}  // namespace tfd::io
