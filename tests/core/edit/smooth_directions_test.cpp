// Repair of a rough non-repeating eigenvector before §6.3 (core/edit/smooth_directions.h).
#include "core/edit/smooth_directions.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <numeric>

#include "core/edit/region_complex.h"
#include "core/error.h"
#include "core/structured_mesh.h"

namespace tfd::core {
namespace {

constexpr double kTurn = std::numbers::pi / 6;

struct Case {
  std::shared_ptr<const TetMesh> mesh = makeBoxMesh(8, 8, 8, Vec3::Constant(-1), Vec3::Ones());
  RegionComplex region;
  std::vector<char> held;
  std::vector<Vec3> directions;
  explicit Case(double turning) {
    std::vector<int> all(mesh->tetCount());
    std::iota(all.begin(), all.end(), 0);
    region = regionComplex(*mesh, all);
    for (int v : region.vertices) {
      const Vec3& p = mesh->positions()[v];
      held.push_back(mesh->isBoundaryVertex(v));
      directions.push_back(
          Vec3(std::cos(turning * p.x()), std::sin(turning * p.x()), 0.3 + 0.2 * p.y())
              .normalized());
    }
  }
  double maxTurn(const std::vector<Vec3>& d) const {
    double worst = 0;
    for (std::size_t a = 0; a < d.size(); ++a)
      for (int k = region.start[a]; k < region.start[a + 1]; ++k)
        worst = std::max(worst, std::acos(std::min(1.0, d[a].dot(d[region.neighbour[k]]))));
    return worst;
  }
  /// The free vertex nearest the centre.
  int centre() const {
    int best = -1;
    for (std::size_t i = 0; i < region.vertices.size(); ++i)
      if (!held[i] && (best < 0 || mesh->positions()[region.vertices[i]].norm() <
                                       mesh->positions()[region.vertices[best]].norm()))
        best = int(i);
    return best;
  }
};

bool same(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

TEST(SmoothDirections, SmoothDirectionsStayBitwise) {
  const Case c(0.4);
  const std::vector<char> weak(c.directions.size(), 1);
  const DirectionRepair r =
      repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2);
  EXPECT_EQ(r.roughEdges, 0);
  EXPECT_EQ(r.solvedVertices, 0);
  for (std::size_t i = 0; i < c.directions.size(); ++i)
    EXPECT_TRUE(same(r.directions[i], c.directions[i]));
}

// A fast turn where N is well defined is §6.3's business (the jumps), not a repair's.
TEST(SmoothDirections, FastTurnsOfAWellDefinedDirectionStay) {
  const Case c(5.0);
  ASSERT_GT(c.maxTurn(c.directions), kTurn);
  const std::vector<char> weak(c.directions.size(), 0);
  const DirectionRepair r =
      repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2);
  EXPECT_EQ(r.roughEdges, 0);
  for (std::size_t i = 0; i < c.directions.size(); ++i)
    EXPECT_TRUE(same(r.directions[i], c.directions[i]));
}

// One weak vertex whose direction is swapped by 90° (an eigenvalue that nearly repeats there):
// only the patch around it moves, and afterwards N turns smoothly everywhere.
TEST(SmoothDirections, SwappedWeakDirectionIsRepairedLocally) {
  Case c(0.4);
  const int v = c.centre();
  const Vec3 d = c.directions[v];
  c.directions[v] = d.cross(Vec3::UnitZ()).normalized();  // 90° off, same sign convention
  ASSERT_GT(c.maxTurn(c.directions), 1.5);
  std::vector<char> weak(c.directions.size(), 0);
  weak[v] = 1;
  const DirectionRepair r =
      repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2);
  EXPECT_GT(r.roughEdges, 0);
  EXPECT_GT(r.solvedVertices, 1);
  EXPECT_GT(r.maxTurnBefore, 1.5);
  EXPECT_LT(c.maxTurn(r.directions), kTurn);
  EXPECT_LT((r.directions[v] - d).norm(), 0.1);  // back near its neighbours' direction
  // Held vertices and every vertex more than three rings from v (two from the far ends of the
  // rough edges) keep their direction bitwise.
  std::vector<int> ring(c.directions.size(), -1), queue{v};
  ring[v] = 0;
  for (std::size_t h = 0; h < queue.size(); ++h)
    for (int k = c.region.start[queue[h]]; k < c.region.start[queue[h] + 1]; ++k)
      if (int n = c.region.neighbour[k]; ring[n] < 0)
        ring[n] = ring[queue[h]] + 1, queue.push_back(n);
  int changed = 0;
  for (std::size_t i = 0; i < c.directions.size(); ++i) {
    EXPECT_NEAR(r.directions[i].norm(), 1.0, 1e-12);
    if (c.held[i] || ring[i] > 3) {  // two rings around the rough edges' ends
      EXPECT_TRUE(same(r.directions[i], c.directions[i])) << i;
    }
    changed += !same(r.directions[i], c.directions[i]);
  }
  EXPECT_EQ(changed, r.solvedVertices);
}

TEST(SmoothDirections, SameResultForOneAndTwoThreads) {
  Case c(0.4);
  const int v = c.centre();
  c.directions[v] = c.directions[v].cross(Vec3::UnitZ()).normalized();
  std::vector<char> weak(c.directions.size(), 0);
  weak[v] = 1;
  DirectionRepair one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2);
  }
  ASSERT_GT(one.solvedVertices, 0);
  for (std::size_t i = 0; i < c.directions.size(); ++i)
    EXPECT_TRUE(same(one.directions[i], two.directions[i]));
}

TEST(SmoothDirections, RefusesMismatchedSizes) {
  const Case c(0.4);
  const std::vector<char> weak(3, 0);
  EXPECT_THROW(repairRoughDirections(*c.mesh, c.region, c.directions, c.held, weak, kTurn, 2),
               Error);
}

}  // namespace
}  // namespace tfd::core
