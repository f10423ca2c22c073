// Boundary curvature tensor (core/surface/surface_curvature.h, Rusinkiewicz 2004) on meshes
// without TetGen: the procedural icosphere coned to its centre (umbilic, k = 1/r), a torus
// mapped from a grid (principal directions along and around the tube) and a box (flat faces).
#include "core/surface/surface_curvature.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/structured_mesh.h"
#include "core/surface/primitives.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

TEST(SurfaceCurvature, SphereIsUmbilicWithCurvatureOneOverRadius) {
  const double r = 1.5;
  // The boundary TetMesh keeps for this primitive at 20000 tets (icosphere), coned to the centre.
  const auto mesh =
      test::coneMesh(makePrimitiveForTets(PrimitiveSpec{PrimitiveShape::Sphere, r}, 20000));
  const auto curvature = boundaryCurvatureTensors(*mesh);
  ASSERT_EQ(curvature.size(), mesh->boundaryVertices().size());
  double sumError = 0, worst = 0;
  for (std::size_t i = 0; i < curvature.size(); ++i) {
    const Vec3& n = mesh->vertexNormals()[mesh->boundaryVertices()[i]];
    const PrincipalCurvatures pc = principalCurvatures(curvature[i], n);
    const double e = std::max(std::abs(pc.k1 - 1 / r), std::abs(pc.k2 - 1 / r)) * r;
    sumError += e;
    worst = std::max(worst, e);
    // Tangent tensor: nothing along the normal.
    EXPECT_LT((curvature[i].matrix() * n).norm(), 1e-12);
  }
  EXPECT_LT(sumError / curvature.size(), 0.04);
  EXPECT_LT(worst, 0.1);
}

TEST(SurfaceCurvature, TorusPrincipalDirectionsRunAroundAndAlongTheTube) {
  const double R = 1.0, a = 0.4;
  const auto mesh = test::mappedTorus(96, 8, R, a);  // boundary vertices on the exact torus
  const auto curvature = boundaryCurvatureTensors(*mesh);
  int outer = 0, inner = 0;
  for (std::size_t i = 0; i < curvature.size(); ++i) {
    const int v = mesh->boundaryVertices()[i];
    const Vec3& p = mesh->positions()[v];
    const double rho = std::hypot(p.x(), p.y());
    if (std::abs(p.z()) > 0.05) continue;                      // equator of the tube only
    const Vec3 azimuth = Vec3(-p.y(), p.x(), 0).normalized();  // along the ring
    const PrincipalCurvatures pc = principalCurvatures(curvature[i], mesh->vertexNormals()[v]);
    // Around the tube: k = 1/a, direction ±z. Along the ring: cosφ / (R + a cosφ).
    EXPECT_NEAR(pc.k1, 1 / a, 0.15 / a) << p.transpose();
    EXPECT_GT(std::abs(pc.d1.z()), 0.95) << p.transpose();
    EXPECT_GT(std::abs(pc.d2.dot(azimuth)), 0.95) << p.transpose();
    if (rho > R) {
      EXPECT_NEAR(pc.k2, 1 / (R + a), 0.2) << p.transpose();
      ++outer;
    } else {
      EXPECT_NEAR(pc.k2, -1 / (R - a), 0.3) << p.transpose();  // saddle side
      ++inner;
    }
  }
  EXPECT_GT(outer, 10);
  EXPECT_GT(inner, 10);
}

TEST(SurfaceCurvature, FlatFacesHaveNoCurvature) {
  const auto mesh = makeBoxMesh(6, 6, 6, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const auto curvature = boundaryCurvatureTensors(*mesh);
  for (std::size_t i = 0; i < curvature.size(); ++i) {
    const Vec3& p = mesh->positions()[mesh->boundaryVertices()[i]];
    const int onFaces = (std::abs(std::abs(p.x()) - 1) < 1e-12) +
                        (std::abs(std::abs(p.y()) - 1) < 1e-12) +
                        (std::abs(std::abs(p.z()) - 1) < 1e-12);
    if (onFaces == 1 && (p.cwiseAbs().array() < 0.5).count() == 2) {
      EXPECT_LT(curvature[i].norm(), 1e-10) << p.transpose();
    }
  }
}

TEST(SurfaceCurvature, LiftKeepsTheNormalAsEigenvector) {
  const Vec3 n = Vec3(1, 2, 2).normalized();
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const Tensor ii = Tensor::fromMatrix(2.0 * t1 * t1.transpose() - 0.5 * t2 * t2.transpose());
  const Tensor lifted = liftCurvatureTensor(ii, n, 3.0);
  EXPECT_NEAR(lifted.trace(), 0, 1e-14);
  const Vec3 ln = lifted.matrix() * n;
  EXPECT_NEAR(ln.dot(n), 3.0 - (2.0 - 0.5 + 3.0) / 3, 1e-13);
  EXPECT_LT((ln - ln.dot(n) * n).norm(), 1e-14);
  const PrincipalCurvatures pc = principalCurvatures(ii, n);
  EXPECT_NEAR(pc.k1, 2.0, 1e-13);
  EXPECT_NEAR(pc.k2, -0.5, 1e-13);
  EXPECT_NEAR(std::abs(pc.d1.dot(t1)), 1, 1e-12);
}

}  // namespace
}  // namespace tfd::core
