#include "core/tet_mesh.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/point_locator.h"
#include "core/structured_mesh.h"

namespace tfd::core {
namespace {

TEST(TetMesh, BoxTopologyCounts) {
  const int n = 3;
  const auto mesh = makeBoxMesh(n, n, n, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  EXPECT_EQ(mesh->tetCount(), 6u * n * n * n);
  EXPECT_EQ(mesh->vertexCount(), 64u);
  // Euler: V − E + F − T = 1 for a ball.
  const long euler = long(mesh->vertexCount()) - long(mesh->edges().size()) +
                     long(mesh->faces().size()) - long(mesh->tetCount());
  EXPECT_EQ(euler, 1);
  EXPECT_EQ(mesh->boundaryFaces().size(), 6u * n * n * 2);
  EXPECT_EQ(mesh->boundaryVertices().size(), 64u - 8u);
  EXPECT_NEAR(mesh->totalVolume(), 8.0, 1e-12);
  for (double v : mesh->tetVolumes()) EXPECT_GT(v, 0);
  // Normals point outward: at a face centre vertex of x = 1 the normal is +x.
  const int v = 3 + 4 * (1 + 4 * 1);
  EXPECT_NEAR((mesh->vertexNormals()[v] - Vec3(1, 0, 0)).norm(), 0, 1e-12);
  for (int f : mesh->boundaryFaces()) {
    const auto o = mesh->orientedBoundaryFace(f);
    const auto& p = mesh->positions();
    const Vec3 c = (p[o[0]] + p[o[1]] + p[o[2]]) / 3;
    EXPECT_GT((p[o[1]] - p[o[0]]).cross(p[o[2]] - p[o[0]]).dot(c), 0);
  }
}

TEST(TetMesh, ValidationNamesTheProblem) {
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  const auto problems = TetMesh::validate(p, {{0, 2, 1, 3}});
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("tet 0 is inverted"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("vertex 4 is used by no tet"), std::string::npos) << problems[1];
  EXPECT_THROW(TetMesh(p, {{0, 1, 2, 7}}), Error);
  try {
    TetMesh(p, {{0, 1, 2, 7}});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("uses vertex 7, out of range"), std::string::npos);
  }
}

TEST(PointLocator, FindsTheContainingTet) {
  const auto mesh = makeBoxMesh(8, 7, 6, Vec3(0, 0, 0), Vec3(1, 2, 3));
  std::vector<Vec3> pts;
  for (int i = 0; i < 2000; ++i)
    pts.push_back(Vec3::Random().cwiseAbs().cwiseProduct(Vec3(1, 2, 3)));
  pts.push_back(Vec3(2, 0, 0));
  const auto found = mesh->locator().locateAll(pts);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    ASSERT_TRUE(found[i].has_value());
    EXPECT_GE(found[i]->barycentric.minCoeff(), -1e-10);
    Vec3 q = Vec3::Zero();
    for (int k = 0; k < 4; ++k)
      q += found[i]->barycentric[k] * mesh->positions()[mesh->tets()[found[i]->tet][k]];
    EXPECT_NEAR((q - pts[i]).norm(), 0, 1e-12);
  }
  EXPECT_FALSE(found.back().has_value());
}

TEST(PointLocator, AgreesWithABruteForceSearchIncludingPointsOnFacesAndVertices) {
  // The answer is defined as the tet with the largest smallest barycentric coordinate (ties:
  // the lower id); the grid's candidate order and early exit must not change it. Points on
  // vertices and face centres of the structured mesh are shared by several tets.
  const auto mesh = makeBoxMesh(4, 4, 4, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) pts.push_back(0.5 * (Vec3::Random() + Vec3::Ones()));
  for (std::size_t v = 0; v < mesh->vertexCount(); v += 7) pts.push_back(mesh->positions()[v]);
  for (std::size_t f = 0; f < mesh->faces().size(); f += 11) {
    const auto& face = mesh->faces()[f];
    pts.push_back(
        (mesh->positions()[face[0]] + mesh->positions()[face[1]] + mesh->positions()[face[2]]) / 3);
  }
  for (const Vec3& p : pts) {
    int bestTet = -1;
    double bestMin = -1e-10;
    for (int t = 0; t < int(mesh->tetCount()); ++t) {
      const double m = mesh->barycentric(t, p).minCoeff();
      if (m > bestMin + 1e-15 || (bestTet >= 0 && std::abs(m - bestMin) <= 1e-15 && t < bestTet) ||
          (bestTet < 0 && m >= bestMin)) {
        bestTet = t;
        bestMin = m;
      }
    }
    const auto found = mesh->locator().locate(p);
    ASSERT_TRUE(found.has_value());
    EXPECT_NEAR(found->barycentric.minCoeff(), bestMin, 1e-12) << p.transpose();
  }
}

}  // namespace
}  // namespace tfd::core
