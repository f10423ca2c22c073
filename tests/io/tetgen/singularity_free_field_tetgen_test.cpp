// The singularity-free field of paper §6.3 on an unstructured TetGen sphere (obtuse tets,
// cotangent weights of both signs): ball regions grown by core/region inside the sphere and
// reaching its surface are propagated in a ball order and come out free of degenerate curves,
// with positive eigenvalue gaps. (Regions cut by a plain distance test are often not balls on
// such meshes: pinched edges.) An io test because the mesh comes from TetGen.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/edit/singularity_free_field.h"
#include "core/point_locator.h"
#include "core/region/ball_check.h"
#include "core/region/ball_region.h"
#include "core/topology/extract_degenerate_curves.h"
#include "io/tetgen/tetgen_mesher.h"

namespace tfd::core {
namespace {

TEST(SingularityFreeFieldTetGen, SphereRegionsInsideAndAtTheSurfaceComeOutCurveFree) {
  const auto mesh = io::meshPrimitive(PrimitiveShape::Sphere, 20000);
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    const Mat3 r = (Eigen::AngleAxisd(2.5 * p.x(), Vec3::UnitY()) *
                    Eigen::AngleAxisd(2.0 * p.y() + 0.5 * p.z(), Vec3::UnitX()))
                       .toRotationMatrix();
    values.push_back(Tensor::fromMatrix(r * Vec3(1.5, -0.2, -1.3).asDiagonal() * r.transpose()));
  }
  const TensorField field(mesh, values);
  ASSERT_TRUE(extractDegenerateCurves(field).empty());
  const std::vector<unsigned char> forbidden(mesh->tetCount(), 0);
  for (const Vec3& centre : {Vec3(0.1, -0.05, 0.02), Vec3(0.45, 0.2, 0.1)}) {
    const auto seed = mesh->locator().locate(centre);
    ASSERT_TRUE(seed.has_value());
    const std::vector<int> seeds{seed->tet};
    const BallRegion region = growBallRegion(*mesh, seeds, forbidden, {.distance = 0.7});
    ASSERT_TRUE(region.complete);
    ASSERT_GT(region.tets.size(), 3000u);
    const BallCheck check = checkTopologicalBall(*mesh, region.tets);
    ASSERT_TRUE(check.ball) << check.problem;
    if (centre.x() > 0.4) {
      EXPECT_GT(check.surfaceFaces, 0) << "the second region reaches the surface";
    }
    SingularityFreeReport report;
    const TensorField after =
        singularityFreeField(field, region.tets, std::vector<char>(mesh->vertexCount(), 0),
                             DegenerateType::Planar, {}, &report);
    EXPECT_EQ(report.nonBallSteps, 0) << report.summary();
    EXPECT_LT(report.maxHolonomyDefect, 1e-12);
    EXPECT_GT(report.freeMinGap12, 0);
    EXPECT_GT(report.freeMinGap23, 0);
    const DegenerateCurves curves = extractDegenerateCurves(after);
    EXPECT_TRUE(curves.empty()) << curves.summary();
  }
}

}  // namespace
}  // namespace tfd::core
