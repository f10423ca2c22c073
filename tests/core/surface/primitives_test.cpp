// Procedural solids: closed, manifold, outward, right genus, right size and volume.
#include "core/surface/primitives.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

struct Case {
  PrimitiveSpec spec;
  long euler;
  double volumeTolerance;  // relative, polyhedral approximation at the test's edge length
};

class PrimitiveTest : public testing::TestWithParam<Case> {};

TEST_P(PrimitiveTest, ClosedManifoldOutwardWithRightGenusAndVolume) {
  const Case& c = GetParam();
  const double edge = 0.08;
  const SurfaceMesh mesh = makePrimitive(c.spec, edge);
  const auto problems = closedSurfaceProblems(mesh);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(eulerCharacteristic(mesh), c.euler);
  const double exact = primitiveVolume(c.spec);
  const double volume = enclosedVolume(mesh);
  EXPECT_GT(volume, 0) << "outward orientation gives a positive enclosed volume";
  EXPECT_NEAR(volume / exact, 1.0, c.volumeTolerance);
  // Edge lengths follow the request.
  EXPECT_NEAR(meanEdgeLength(mesh) / edge, 1.0, 0.2);
  // Every triangle is reasonably shaped (no slivers): min angle above ~15 degrees.
  double worst = 180;
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = mesh.positions[t[(i + 1) % 3]] - mesh.positions[t[i]];
      const Vec3 b = mesh.positions[t[(i + 2) % 3]] - mesh.positions[t[i]];
      worst =
          std::min(worst, std::acos(a.normalized().dot(b.normalized())) * 180 / std::numbers::pi);
    }
  }
  EXPECT_GT(worst, 15.0) << primitiveShapeName(c.spec.shape);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, PrimitiveTest,
    testing::Values(Case{{.shape = PrimitiveShape::Sphere, .radius = 1.0}, 2, 0.01},
                    Case{{.shape = PrimitiveShape::Box, .size = Vec3(1, 2, 0.5)}, 2, 1e-12},
                    Case{{.shape = PrimitiveShape::Torus}, 0, 0.02},
                    Case{{.shape = PrimitiveShape::DoubleTorus}, -2, 0.03}),
    [](const auto& info) { return primitiveShapeName(info.param.spec.shape); });

TEST(Primitives, SphereVerticesLieOnTheSphere) {
  const SurfaceMesh mesh = makeSphere(2.5, 0.3);
  for (const Vec3& p : mesh.positions) EXPECT_NEAR(p.norm(), 2.5, 1e-12);
}

TEST(Primitives, DoubleTorusIsDeterministicForAnyThreadCount) {
  SurfaceMesh one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = makeDoubleTorus(1.0, 0.4, 0.1);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = makeDoubleTorus(1.0, 0.4, 0.1);
  }
  ASSERT_EQ(one.positions.size(), two.positions.size());
  EXPECT_EQ(one.triangles, two.triangles);
  for (std::size_t i = 0; i < one.positions.size(); ++i)
    EXPECT_EQ(one.positions[i], two.positions[i]);
}

TEST(Primitives, DoubleTorusVolumeIntegralIsConsistent) {
  // Two disjoint-ish tori would give 2 · 2π²Rr²; the blend adds a little, the overlap removes
  // a little: the estimate must be close to that and to the fine polygonised volume.
  PrimitiveSpec spec{.shape = PrimitiveShape::DoubleTorus};
  const double v = primitiveVolume(spec);
  const double twoTori = 2 * 2 * std::numbers::pi * std::numbers::pi * 1.0 * 0.16;
  EXPECT_NEAR(v / twoTori, 1.0, 0.1);
  EXPECT_NEAR(enclosedVolume(makeDoubleTorus(1.0, 0.4, 0.04)) / v, 1.0, 0.01);
}

TEST(Primitives, TargetTetCountDrivesResolution) {
  PrimitiveSpec spec{.shape = PrimitiveShape::Sphere};
  const auto coarse = makePrimitiveForTets(spec, 10'000);
  const auto fine = makePrimitiveForTets(spec, 80'000);
  // 8x the tets -> half the edge length -> about 4x the triangles.
  EXPECT_NEAR(double(fine.triangles.size()) / coarse.triangles.size(), 4.0, 0.8);
}

TEST(Primitives, BadParametersAreNamed) {
  try {
    makeTorus(1.0, 1.5, 0.1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("minor radius"), std::string::npos) << e.what();
  }
  try {
    makeSphere(-1, 0.1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
  }
  EXPECT_THROW(makeBox(Vec3(1, 1, 1), 0), Error);
}

}  // namespace
}  // namespace tfd::core
