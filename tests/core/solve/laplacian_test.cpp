// P1 stiffness matrix (core/solve/laplacian.h): symmetry, zero row sums, the Dirichlet energy of
// linear functions, the cotangent formula, subsets, determinism.
#include "core/solve/laplacian.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/error.h"
#include "tests/core/solve/solver_test_meshes.h"

namespace tfd::core {
namespace {

using testing::hashUnit;
using testing::jitteredBox;

double entryOf(const linalg::CsrMatrix<double>& k, int row, int col, bool* found = nullptr) {
  for (int m = k.start[row]; m < k.start[row + 1]; ++m)
    if (k.index[m] == col) {
      if (found) *found = true;
      return k.value[m];
    }
  if (found) *found = false;
  return 0;
}

TEST(Laplacian, TetStiffnessIsTheCotangentFormula) {
  // K_ij = −(1/6) |e_kl| cot θ_kl, with e_kl the edge opposite to edge ij and θ_kl the dihedral
  // angle at e_kl.
  const std::array<Vec3, 4> p = {Vec3(0.1, -0.2, 0.05), Vec3(1.3, 0.1, -0.1), Vec3(0.2, 1.1, 0.3),
                                 Vec3(0.4, 0.3, 1.2)};
  const auto k = tetStiffness(p[0], p[1], p[2], p[3]);
  const int pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e) {
    const int i = pairs[e][0], j = pairs[e][1];
    int kl[2], c = 0;
    for (int m = 0; m < 4; ++m)
      if (m != i && m != j) kl[c++] = m;
    const Vec3 edge = p[kl[1]] - p[kl[0]];
    // Normals of the two faces sharing edge kl (faces kl+i and kl+j), pointing away from it.
    const Vec3 u = edge.normalized();
    Vec3 a = p[i] - p[kl[0]], b = p[j] - p[kl[0]];
    a -= a.dot(u) * u;
    b -= b.dot(u) * u;
    const double cosTheta = a.normalized().dot(b.normalized());
    const double sinTheta = a.normalized().cross(b.normalized()).norm();
    const double expected = -edge.norm() * (cosTheta / sinTheta) / 6.0;
    EXPECT_NEAR(k[e], expected, 1e-13) << "edge " << i << j;
  }
}

TEST(Laplacian, SymmetricRowsSumToZeroAndPatternIsTheMeshGraph) {
  const auto mesh = jitteredBox(6);
  const StiffnessRows k = assembleStiffness(*mesh);
  ASSERT_EQ(k.vertices.size(), mesh->vertexCount());
  std::size_t positive = 0, offDiagonal = 0;
  for (int i = 0; i < k.matrix.rows; ++i) {
    double sum = 0, diag = 0;
    for (int m = k.matrix.start[i]; m < k.matrix.start[i + 1]; ++m) {
      const int j = k.matrix.index[m];
      sum += k.matrix.value[m];
      if (j == i) {
        diag = k.matrix.value[m];
        continue;
      }
      ++offDiagonal;
      positive += k.matrix.value[m] > 0;
      bool found = false;
      const double kji = entryOf(k.matrix, j, i, &found);
      ASSERT_TRUE(found);
      EXPECT_EQ(kji, k.matrix.value[m]) << "K is not bitwise symmetric at " << i << "," << j;
    }
    EXPECT_GT(diag, 0);
    EXPECT_LE(std::abs(sum), 1e-13 * diag) << "row " << i;
  }
  EXPECT_EQ(offDiagonal, 2 * mesh->edges().size());
  // The jittered mesh is not an M-matrix: the tests below do not rely on a maximum principle.
  EXPECT_GT(positive, 0u);
}

TEST(Laplacian, EnergyOfALinearFunctionIsVolumeTimesGradientSquared) {
  const auto mesh = jitteredBox(7);
  const StiffnessRows k = assembleStiffness(*mesh);
  const Vec3 g(0.7, -1.3, 0.4);
  std::vector<double> u(mesh->vertexCount());
  for (std::size_t v = 0; v < u.size(); ++v) u[v] = g.dot(mesh->positions()[v]) + 2.5;
  const std::vector<double> ku = applyStiffness(k, u);
  double energy = 0;
  for (std::size_t v = 0; v < u.size(); ++v) energy += u[v] * ku[v];
  const double expected = mesh->totalVolume() * g.squaredNorm();
  EXPECT_NEAR(energy, expected, 1e-10 * expected);
  EXPECT_NEAR(gradientEnergy(*mesh, u), expected, 1e-10 * expected);
  // Interior rows annihilate linear functions (discrete harmonicity of linear fields).
  for (std::size_t v = 0; v < u.size(); ++v)
    if (!mesh->isBoundaryVertex(static_cast<int>(v))) {
      EXPECT_NEAR(ku[v], 0, 1e-12);
    }
  // Constants are in the null space.
  const std::vector<double> ones(u.size(), 1.0);
  for (double r : applyStiffness(k, ones)) EXPECT_NEAR(r, 0, 1e-13);
}

TEST(Laplacian, PositiveSemidefiniteAndEqualToTheGradientEnergy) {
  const auto mesh = jitteredBox(5);
  const StiffnessRows k = assembleStiffness(*mesh);
  std::vector<double> u(mesh->vertexCount());
  for (std::size_t v = 0; v < u.size(); ++v) u[v] = hashUnit(v);
  const std::vector<double> ku = applyStiffness(k, u);
  double energy = 0;
  for (std::size_t v = 0; v < u.size(); ++v) energy += u[v] * ku[v];
  EXPECT_GT(energy, 0);
  EXPECT_NEAR(energy, gradientEnergy(*mesh, u), 1e-11 * energy);
}

TEST(Laplacian, SubsetRowsEqualTheFullRowsBitwise) {
  const auto mesh = jitteredBox(6);
  const StiffnessRows full = assembleStiffness(*mesh);
  const int n = static_cast<int>(mesh->vertexCount());
  // A few scattered rows (entries computed per row) and a region of 40 % of the vertices
  // (entries computed once for each tet around it).
  std::vector<int> scattered, region;
  for (int v = 3; v < n; v += 7) scattered.push_back(v);
  for (int v = n / 5; v < 3 * n / 5; ++v) region.push_back(v);
  for (const std::vector<int>& some : {scattered, region}) {
    const StiffnessRows part = assembleStiffnessRows(*mesh, some);
    ASSERT_EQ(part.matrix.rows, static_cast<int>(some.size()));
    for (std::size_t r = 0; r < some.size(); ++r) {
      const int v = some[r];
      ASSERT_EQ(part.matrix.start[r + 1] - part.matrix.start[r],
                full.matrix.start[v + 1] - full.matrix.start[v]);
      for (int m = 0; m < part.matrix.start[r + 1] - part.matrix.start[r]; ++m) {
        EXPECT_EQ(part.matrix.index[part.matrix.start[r] + m],
                  full.matrix.index[full.matrix.start[v] + m]);
        EXPECT_EQ(part.matrix.value[part.matrix.start[r] + m],
                  full.matrix.value[full.matrix.start[v] + m]);
      }
    }
  }
  EXPECT_THROW(assembleStiffnessRows(*mesh, {5, 3}), Error);
  EXPECT_THROW(assembleStiffnessRows(*mesh, {-1}), Error);
  EXPECT_THROW(assembleStiffnessRows(*mesh, {static_cast<int>(mesh->vertexCount())}), Error);
}

TEST(Laplacian, DeterministicForOneAndTwoThreads) {
  const auto mesh = jitteredBox(12);
  StiffnessRows one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = assembleStiffness(*mesh);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = assembleStiffness(*mesh);
  }
  EXPECT_EQ(one.matrix.index, two.matrix.index);
  EXPECT_EQ(one.matrix.value, two.matrix.value);
}

}  // namespace
}  // namespace tfd::core
