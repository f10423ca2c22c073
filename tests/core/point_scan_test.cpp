// locateByScan (no grid) against PointLocator::locate: the same tet and bitwise the same
// barycentric coordinates for points inside tets, on shared faces, edges and vertices, and
// none for points outside; locatePoints leaves the grid unbuilt for a few points.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "core/point_locator.h"
#include "core/structured_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::core {
namespace {

std::vector<Vec3> probePoints(const TetMesh& mesh) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<Vec3> pts;
  for (int i = 0; i < 200; ++i) pts.push_back(Vec3(u(rng), u(rng), u(rng)));  // some outside
  const auto& p = mesh.positions();
  for (std::size_t v = 0; v < mesh.vertexCount(); v += 5) pts.push_back(p[v]);
  for (std::size_t e = 0; e < mesh.edges().size(); e += 9)
    pts.push_back(0.5 * (p[mesh.edges()[e][0]] + p[mesh.edges()[e][1]]));
  for (std::size_t f = 0; f < mesh.faces().size(); f += 7) {
    const auto& k = mesh.faces()[f];
    pts.push_back((p[k[0]] + p[k[1]] + p[k[2]]) / 3);
  }
  // Just outside: beyond a boundary face by a little and by less than the tolerance.
  for (std::size_t i = 0; i < mesh.boundaryFaces().size(); i += 13) {
    const auto k = mesh.orientedBoundaryFace(mesh.boundaryFaces()[i]);
    const Vec3 n = (p[k[1]] - p[k[0]]).cross(p[k[2]] - p[k[0]]).normalized();
    const Vec3 c = (p[k[0]] + p[k[1]] + p[k[2]]) / 3;
    pts.push_back(c + 1e-6 * n);
    pts.push_back(c + 1e-13 * n);
  }
  pts.push_back(Vec3(5, 0, 0));
  return pts;
}

TEST(PointScan, SameAnswersAsTheGrid) {
  // A carved (non-convex) mesh: a box with a slab removed, so some points in the bounds fall
  // into the gap.
  const auto box = makeBoxMesh(6, 7, 5, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  std::vector<int> index(box->vertexCount(), -1);
  std::vector<Vec3> positions;
  std::vector<TetMesh::Tet> tets;
  for (const auto& t : box->tets()) {
    Vec3 c = Vec3::Zero();
    for (int v : t) c += 0.25 * box->positions()[v];
    if (std::abs(c.x()) < 0.34 && c.y() > 0) continue;
    TetMesh::Tet kept;
    for (int i = 0; i < 4; ++i) {
      if (index[t[i]] < 0) {
        index[t[i]] = int(positions.size());
        positions.push_back(box->positions()[t[i]]);
      }
      kept[i] = index[t[i]];
    }
    tets.push_back(kept);
  }
  const auto mesh = std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
  const auto pts = probePoints(*mesh);
  const auto scanned = locateByScan(*mesh, pts);
  EXPECT_FALSE(mesh->hasLocator());
  int inside = 0, outside = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto expected = mesh->locator().locate(pts[i]);
    ASSERT_EQ(scanned[i].has_value(), expected.has_value()) << pts[i].transpose();
    if (!expected) {
      ++outside;
      continue;
    }
    ++inside;
    EXPECT_EQ(scanned[i]->tet, expected->tet) << pts[i].transpose();
    EXPECT_EQ(scanned[i]->barycentric, expected->barycentric) << pts[i].transpose();
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(outside, 50);
}

TEST(PointScan, TiesGoToTheLowerTetAndThreadsDoNotMatter) {
  const auto mesh = makeBoxMesh(20, 20, 20, Vec3(0, 0, 0), Vec3(1, 1, 1));  // 48,000 tets
  // A vertex inside the box: every tet around it has smallest coordinate 0.
  // A vertex and a point on a shared face, then one outside.
  std::vector<Vec3> pts = {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.52, 0.51), Vec3(2, 2, 2)};
  const auto one = [&] {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    return locateByScan(*mesh, pts);
  }();
  const auto two = [&] {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    return locateByScan(*mesh, pts);
  }();
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(one[k] && two[k]);
    EXPECT_EQ(one[k]->tet, two[k]->tet);
    EXPECT_EQ(one[k]->barycentric, two[k]->barycentric);
    // The rule, by definition: the largest smallest coordinate, exact ties to the lower id.
    int best = -1;
    double bestMin = 0;
    int ties = 0;
    for (int t = 0; t < int(mesh->tetCount()); ++t) {
      const double m = mesh->barycentric(t, pts[k]).minCoeff();
      if (m < -1e-10) continue;
      ties += m > -1e-12;
      if (best < 0 || m > bestMin) best = t, bestMin = m;
    }
    EXPECT_GE(ties, 2);  // on a vertex or a face: several tets hold the point
    EXPECT_EQ(one[k]->tet, best);
    EXPECT_EQ(mesh->locator().locate(pts[k])->tet, best);
  }
  EXPECT_FALSE(one[2] || two[2]);
}

TEST(PointScan, LocatePointsBuildsTheGridOnlyForManyPoints) {
  const auto mesh = makeBoxMesh(5, 5, 5, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Vec3> few(3, Vec3(0.3, 0.4, 0.5));
  const auto a = locatePoints(*mesh, few);
  EXPECT_FALSE(mesh->hasLocator());
  std::vector<Vec3> many(kScanPointLimit + 1, Vec3(0.3, 0.4, 0.5));
  const auto b = locatePoints(*mesh, many);
  EXPECT_TRUE(mesh->hasLocator());
  EXPECT_EQ(a[0]->tet, b[0]->tet);
  EXPECT_EQ(a[0]->barycentric, b[0]->barycentric);
}

}  // namespace
}  // namespace tfd::core
