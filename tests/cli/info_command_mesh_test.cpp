// `tfd info` of mesh files: counts and the topology of the surface, worded by apps/tfd.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
#include "io/mesh_file.h"
#include "io/tetgen/tetgen_mesher.h"
#include "tests/support/cli_runner.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(InfoMesh, ReportsCountsAndTopology) {
  if (!cliAvailable()) GTEST_SKIP() << "tfd binary not built";
  const fs::path dir = fs::temp_directory_path() / ("tfd_info_mesh_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path torus = dir / "torus.ply";
  const core::SurfaceMesh surface = core::makeTorus(1.0, 0.4, 0.2);
  io::writeSurfaceMesh(torus, surface);
  CliRun r = runCli("info " + shellQuote(torus.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.out, "PLY (binary_little_endian) (surface mesh)")) << r.out;
  EXPECT_TRUE(has(r.out, "triangles:")) << r.out;
  EXPECT_TRUE(has(r.out, " " + std::to_string(surface.triangles.size()) + "\n")) << r.out;
  EXPECT_TRUE(has(r.out, "Euler characteristic 0 (genus 1)")) << r.out;

  const auto mesh = io::meshPrimitive(core::PrimitiveShape::DoubleTorus, 3000);
  const fs::path msh = dir / "dt.msh";
  io::writeTetMesh(msh, *mesh);
  r = runCli("info " + shellQuote(msh.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.out, "Gmsh .msh 4.1 (ASCII) (tet mesh)")) << r.out;
  EXPECT_TRUE(has(r.out, " " + std::to_string(mesh->tetCount()) + "\n")) << r.out;
  EXPECT_TRUE(has(r.out, "1 component, Euler characteristic -2 (genus 2)")) << r.out;
  fs::remove_all(dir);
}

TEST(InfoMesh, SaysWhatTheTetMeshNodeRepairsAndWhatSolidItGets) {
  if (!cliAvailable()) GTEST_SKIP() << "tfd binary not built";
  const fs::path dir = fs::temp_directory_path() / ("tfd_info_repair_" + std::to_string(getpid()));
  fs::create_directories(dir);
  // A hollow ball (the inner shell faces inward) with three triangles of the outer one wound
  // the wrong way.
  core::SurfaceMesh surface = core::makeSphere(1.0, 0.3);
  const std::size_t outer = surface.triangles.size();
  core::SurfaceMesh inner = core::makeSphere(0.5, 0.3);
  core::flipOrientation(inner);
  const int base = int(surface.positions.size());
  surface.positions.insert(surface.positions.end(), inner.positions.begin(), inner.positions.end());
  for (const auto& t : inner.triangles)
    surface.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  for (std::size_t t : {std::size_t(0), outer / 2, outer - 1})
    std::swap(surface.triangles[t][1], surface.triangles[t][2]);
  const fs::path file = dir / "hollow.off";
  io::writeSurfaceMesh(file, surface);
  const CliRun r = runCli("info " + shellQuote(file.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.out, "(inconsistent orientation)\n")) << "as written: " << r.out;
  EXPECT_TRUE(has(r.out, "TetMesh node:")) << r.out;
  EXPECT_TRUE(has(r.out, " reverses 3 triangles; solid volume ")) << r.out;
  EXPECT_TRUE(has(r.out, " with 1 void kept empty\n")) << r.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tfd::test
