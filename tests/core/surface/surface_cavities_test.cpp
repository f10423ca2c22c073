#include "core/surface/surface_cavities.h"

#include <gtest/gtest.h>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

/// Spheres about the origin (radius, outward or not) as one surface, in the order given.
SurfaceMesh shells(const std::vector<std::pair<double, bool>>& spheres) {
  SurfaceMesh all;
  for (const auto& [radius, outward] : spheres) {
    SurfaceMesh s = makeSphere(radius, 0.15);
    if (!outward) flipOrientation(s);
    const int base = int(all.positions.size());
    all.positions.insert(all.positions.end(), s.positions.begin(), s.positions.end());
    for (const auto& t : s.triangles)
      all.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  return all;
}

TEST(SurfaceCavities, AnInwardShellInsideAnOutwardOneBoundsACavity) {
  const auto points = cavityPoints(shells({{0.5, false}, {1.0, true}}));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT(points[0].norm(), 0.5) << "inside the inner shell, the void";
  EXPECT_GT(points[0].norm(), 0.45) << "just off it";
}

TEST(SurfaceCavities, EitherOverallOrientationFindsTheSameVoid) {
  const auto points = cavityPoints(shells({{1.0, false}, {0.5, true}}));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT(points[0].norm(), 0.5);
}

TEST(SurfaceCavities, ABallInsideAVoidIsSolidAgain) {
  const auto points = cavityPoints(shells({{1.0, true}, {0.6, false}, {0.3, true}}));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT(points[0].norm(), 0.6);
  EXPECT_GT(points[0].norm(), 0.3) << "between the void's wall and the ball inside it";
}

TEST(SurfaceCavities, SeparateSolidsAndASingleShellHaveNone) {
  SurfaceMesh two = makeSphere(0.4, 0.15);
  const SurfaceMesh other = makeSphere(0.4, 0.15);
  const int base = int(two.positions.size());
  for (const Vec3& p : other.positions) two.positions.push_back(p + Vec3(1, 0, 0));
  for (const auto& t : other.triangles)
    two.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  EXPECT_TRUE(cavityPoints(two).empty());
  EXPECT_TRUE(cavityPoints(makeSphere(1, 0.2)).empty());
  EXPECT_TRUE(cavityPoints(SurfaceMesh{}).empty());
}

}  // namespace
}  // namespace tfd::core
