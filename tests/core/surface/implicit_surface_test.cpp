// polygonizeImplicit's vertex numbering is part of its result: the remeshing and TetGen start
// from it, so the double torus of examples/genus2_*.tfd.json depended on it. It was left to the
// compiler (three calls with side effects as one call's arguments): Clang numbered the crossings
// of a tet the other way round from GCC and made another mesh, another field and other curves.
#include <gtest/gtest.h>

#include "core/surface/implicit_surface.h"

namespace tfd::core {
namespace {

TEST(PolygonizeImplicit, NumbersTheCrossingsTheSameWithEveryCompiler) {
  auto f = [](const Vec3& p) { return p.norm() - 0.7; };
  const SurfaceMesh m = polygonizeImplicit(f, Vec3::Constant(-1), Vec3::Constant(1), 0.5);
  ASSERT_EQ(m.positions.size(), 74u);
  ASSERT_EQ(m.triangles.size(), 144u);
  // The first tet with a crossing has one corner inside: its three crossings are numbered from
  // the last edge to the first (the order GCC had chosen, kept).
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{2, 0, 1}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{2, 1, 3}));
  EXPECT_EQ(m.positions[0], Vec3(0, 0, -0x1.6666666666666p-1));
  EXPECT_EQ(m.positions[1], Vec3(0, -0x1.6ae658c5e8f28p-3, -0x1.5ab996317a3c9p-1));
  EXPECT_EQ(m.positions[2],
            Vec3(-0x1.4af9642969218p-3, -0x1.4af9642969218p-3, -0x1.52be590a5a486p-1));
}

}  // namespace
}  // namespace tfd::core
