// TetGen adapter: topology, orientation, count, volume, determinism and error messages.
#include "io/tetgen/tetgen_mesher.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
#include "io/mesh/surface_writers.h"
#include "io/mesh_file.h"

namespace tfd::io {
namespace {

using core::PrimitiveShape;
using core::PrimitiveSpec;
using core::SurfaceMesh;
using core::Vec3;

/// The boundary of a tet mesh as a surface (outward triangles).
SurfaceMesh boundaryOf(const core::TetMesh& mesh) {
  SurfaceMesh s;
  s.positions = mesh.positions();
  for (int f : mesh.boundaryFaces()) s.triangles.push_back(mesh.orientedBoundaryFace(f));
  core::removeUnreferencedVertices(s);
  return s;
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const core::Error& e) {
    return e.what();
  }
  return "(no error)";
}

struct Case {
  PrimitiveShape shape;
  long euler;
};

class TetgenPrimitive : public testing::TestWithParam<Case> {};

TEST_P(TetgenPrimitive, MeshesTheSolidFaithfully) {
  const Case c = GetParam();
  PrimitiveSpec spec{.shape = c.shape};
  const double target = 20'000;
  const SurfaceMesh surface = core::makePrimitiveForTets(spec, target);
  const auto mesh = tetrahedralize(surface, {.targetTets = target});

  // Topology of the solid: the boundary has the surface's Euler characteristic.
  const SurfaceMesh boundary = boundaryOf(*mesh);
  EXPECT_TRUE(core::closedSurfaceProblems(boundary).empty());
  EXPECT_EQ(core::eulerCharacteristic(boundary), c.euler);
  // Y keeps the boundary: exactly the input triangles, no Steiner points on it.
  EXPECT_EQ(boundary.triangles.size(), surface.triangles.size());
  EXPECT_EQ(mesh->boundaryVertices().size(), surface.positions.size());
  // Every tet positively oriented.
  for (double v : mesh->tetVolumes()) ASSERT_GT(v, 0);
  // Count near the target, volume equal to the surface's and close to the exact solid's.
  EXPECT_NEAR(double(mesh->tetCount()) / target, 1.0, 0.25) << mesh->tetCount();
  EXPECT_NEAR(mesh->totalVolume() / core::enclosedVolume(surface), 1.0, 1e-9);
  EXPECT_NEAR(mesh->totalVolume() / core::primitiveVolume(spec), 1.0, 0.03);
  // Quality: interior edges about as long as the boundary edges.
  EXPECT_NEAR(mesh->meanEdgeLength() / core::meanEdgeLength(surface), 1.0, 0.25);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, TetgenPrimitive,
    testing::Values(Case{PrimitiveShape::Sphere, 2}, Case{PrimitiveShape::Box, 2},
                    Case{PrimitiveShape::Torus, 0}, Case{PrimitiveShape::DoubleTorus, -2}),
    [](const auto& info) { return core::primitiveShapeName(info.param.shape); });

TEST(Tetgen, TetCountFollowsTheTargetOverARange) {
  for (double target : {5'000.0, 40'000.0}) {
    const auto mesh = meshPrimitive(core::PrimitiveShape::Sphere, target);
    EXPECT_NEAR(double(mesh->tetCount()) / target, 1.0, 0.25) << target;
  }
}

TEST(Tetgen, SameInputGivesTheIdenticalMeshForAnyThreadCount) {
  const SurfaceMesh surface = core::makeTorus(1.0, 0.4, 0.15);
  std::shared_ptr<const core::TetMesh> a, b;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    a = tetrahedralize(surface, {.targetTets = 8'000});
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    b = tetrahedralize(surface, {.targetTets = 8'000});
  }
  EXPECT_EQ(a->tets(), b->tets());
  EXPECT_EQ(a->positions(), b->positions());
  EXPECT_EQ(a->edges(), b->edges());
}

// TetGen numbers Steiner points and tets in refinement order; tetrahedralize() renumbers them
// along a Hilbert curve (core/spatial_order.h) so that face neighbours are near in id: before,
// they were ~20 % of the tet count apart at the median. The input surface keeps its ids.
TEST(Tetgen, NumbersTetsAndSteinerPointsInSpatialOrderAndKeepsTheSurfaceIds) {
  const SurfaceMesh surface = core::makeTorus(1.0, 0.4, 0.15);
  const auto mesh = tetrahedralize(surface, {.targetTets = 20'000});
  std::vector<long> gaps;
  for (const auto& ft : mesh->faceTets())
    if (ft[1] >= 0) gaps.push_back(std::labs(long(ft[0]) - long(ft[1])));
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  EXPECT_LT(gaps[gaps.size() / 2], long(mesh->tetCount()) / 100);
  ASSERT_GE(mesh->vertexCount(), surface.positions.size());
  for (std::size_t v = 0; v < surface.positions.size(); ++v)
    ASSERT_EQ(mesh->positions()[v], surface.positions[v]) << v;
}

TEST(Tetgen, EitherSurfaceOrientationWorks) {
  SurfaceMesh surface = core::makeSphere(1.0, 0.3);
  core::flipOrientation(surface);
  const auto mesh = tetrahedralize(surface, {.targetTets = 2'000});
  for (double v : mesh->tetVolumes()) ASSERT_GT(v, 0);
  EXPECT_NEAR(mesh->totalVolume(), -core::enclosedVolume(surface), 1e-9);
}

TEST(Tetgen, ShellsFacingInwardBoundVoidsThatStayEmpty) {
  // A hollow ball holding a smaller ball in its void: outward, inward, outward shells. TetGen
  // alone fills the void; its hole point keeps it empty, and the inner ball stays solid.
  SurfaceMesh surface;
  for (const auto& [radius, outward] : {std::pair{1.0, true}, {0.6, false}, {0.3, true}}) {
    SurfaceMesh s = core::makeSphere(radius, 0.15);
    if (!outward) core::flipOrientation(s);
    const int base = int(surface.positions.size());
    surface.positions.insert(surface.positions.end(), s.positions.begin(), s.positions.end());
    for (const auto& t : s.triangles)
      surface.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  const auto mesh = tetrahedralize(surface, {.targetTets = 20'000});
  for (double v : mesh->tetVolumes()) ASSERT_GT(v, 0);
  EXPECT_NEAR(mesh->totalVolume(), core::enclosedVolume(surface), 1e-9)
      << "the outer ball less the void plus the ball inside it";
  EXPECT_EQ(mesh->boundaryFaces().size(), surface.triangles.size()) << "every shell is boundary";
}

TEST(Tetgen, WithoutKeepBoundaryTheSurfaceIsRefined) {
  const SurfaceMesh surface = core::makeBox(Vec3(1, 1, 1), 1.0);  // 12 triangles
  const auto mesh = tetrahedralize(surface, {.targetTets = 3'000, .keepBoundary = false});
  EXPECT_GT(mesh->boundaryFaces().size(), 12u);
  EXPECT_NEAR(mesh->totalVolume(), 1.0, 1e-9);
}

TEST(Tetgen, SwitchesAreChosenDeliberately) {
  EXPECT_EQ(tetgenSwitches(2.0, {.targetTets = 1000, .quality = 1.5, .volumeFactor = 1.0}),
            "pzQYq1.5a0.002000000000000");
  EXPECT_EQ(tetgenSwitches(2.0, {.targetTets = 0, .quality = 0, .keepBoundary = false}), "pzQ");
}

TEST(Tetgen, SelfIntersectingSurfaceIsReportedAsSuch) {
  // Two overlapping cubes in one surface: each closed, together self-intersecting.
  SurfaceMesh a = core::makeBox(Vec3(1, 1, 1), 0.5);
  const SurfaceMesh b = core::makeBox(Vec3(1, 1, 1), 0.5);
  const int offset = int(a.positions.size());
  for (const Vec3& p : b.positions) a.positions.push_back(p + Vec3(0.5, 0.3, 0.2));
  for (const auto& t : b.triangles)
    a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  // Through a file, as a user would meet it: the message names the file.
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("tfd_tetgen_overlapping_cubes_" + std::to_string(::getpid()) + ".off"))
                               .string();
  writeOff(path, a);
  const std::string m = messageOf([&] {
    tetrahedralize(readSurfaceMesh(path), {.targetTets = 1000, .source = "file '" + path + "'"});
  });
  std::filesystem::remove(path);
  EXPECT_EQ(m.rfind("file '" + path + "': the input surface intersects itself", 0), 0u) << m;
  EXPECT_NE(m.find("repair"), std::string::npos) << m;
  // TetGen's own diagnostics end up in the message, not on stdout.
  EXPECT_NE(m.find("[TetGen: "), std::string::npos) << m;
}

TEST(Tetgen, BadSurfacesAreRejectedBeforeTetgen) {
  SurfaceMesh open = core::makeSphere(1.0, 0.5);
  open.triangles.pop_back();
  std::string m = messageOf([&] { tetrahedralize(open, {}); });
  EXPECT_NE(m.find("the surface is not a closed"), std::string::npos) << m;
  EXPECT_NE(m.find("not closed"), std::string::npos) << m;

  SurfaceMesh flipped = core::makeSphere(1.0, 0.5);
  std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
  m = messageOf([&] { tetrahedralize(flipped, {}); });
  EXPECT_NE(m.find("inconsistent orientation"), std::string::npos) << m;

  // Two closed spheres touching at one point: each vertex of the pair is distinct by id but
  // one position appears twice.
  SurfaceMesh touching = core::makeSphere(1.0, 0.5);
  const Vec3 p = touching.positions[0];
  const int n = int(touching.positions.size());
  for (int v = 0; v < n; ++v) touching.positions.push_back(touching.positions[v] + 2 * p);
  for (int t = 0, count = int(touching.triangles.size()); t < count; ++t) {
    const auto tri = touching.triangles[t];
    touching.triangles.push_back({tri[0] + n, tri[1] + n, tri[2] + n});
  }
  m = messageOf([&] { tetrahedralize(touching, {}); });
  EXPECT_NE(m.find("same position"), std::string::npos) << m;

  m = messageOf([&] { tetrahedralize(SurfaceMesh{}, {}); });
  EXPECT_NE(m.find("no triangles"), std::string::npos) << m;

  m = messageOf([&] { tetrahedralize(core::makeSphere(1, 0.5), {.quality = 0.5}); });
  EXPECT_NE(m.find("quality"), std::string::npos) << m;
}

TEST(Tetgen, CancelledBeforeStartThrowsCancelled) {
  std::atomic<bool> cancel{true};
  core::Progress progress({}, &cancel);
  EXPECT_THROW(tetrahedralize(core::makeSphere(1, 0.3), {}, progress), core::Cancelled);
}

}  // namespace
}  // namespace tfd::io
