// `tfd info` of mesh files: counts and the topology of the surface, worded by apps/tfd.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/surface/primitives.h"
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

}  // namespace
}  // namespace tfd::test
