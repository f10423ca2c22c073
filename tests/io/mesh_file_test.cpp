// Format dispatch by extension and the mesh file description used by `tfd info`.
#include "io/mesh_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "core/error.h"
#include "core/surface/primitives.h"
#include "io/tetgen_mesher.h"

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
  const auto mesh = meshPrimitive("sphere", 2000);
  for (const char* ext : {".node", ".msh", ".vtu"}) {
    const fs::path p = dir_ / (std::string("t") + ext);
    writeTetMesh(p, *mesh);
    const auto back = readTetMesh(p);
    EXPECT_EQ(back->tets(), mesh->tets()) << ext;
    EXPECT_EQ(back->positions(), mesh->positions()) << ext;
  }
}

TEST_F(MeshFile, DescriptionsReportCountsAndTopology) {
  const fs::path torus = dir_ / "torus.ply";
  const core::SurfaceMesh surface = core::makeTorus(1.0, 0.4, 0.2);
  writeSurfaceMesh(torus, surface);
  auto rows = describeMeshFile(torus);
  std::map<std::string, std::string> info(rows.begin(), rows.end());
  EXPECT_EQ(info["format"], "PLY (binary_little_endian) (surface mesh)");
  EXPECT_EQ(info["triangles"], std::to_string(surface.triangles.size()));
  EXPECT_NE(info["closed"].find("Euler characteristic 0 (genus 1)"), std::string::npos)
      << info["closed"];

  const auto mesh = meshPrimitive("double_torus", 3000);
  const fs::path msh = dir_ / "dt.msh";
  writeTetMesh(msh, *mesh);
  rows = describeMeshFile(msh);
  info = std::map<std::string, std::string>(rows.begin(), rows.end());
  EXPECT_EQ(info["format"], "Gmsh .msh 4.1 (ASCII) (tet mesh)");
  EXPECT_EQ(info["tets"], std::to_string(mesh->tetCount()));
  EXPECT_NE(info["boundary"].find("1 component, Euler characteristic -2 (genus 2)"),
            std::string::npos)
      << info["boundary"];
  const std::string text = formatDescription(rows);
  EXPECT_NE(text.find("tets:"), std::string::npos);
}

}  // namespace
}  // namespace tfd::io
