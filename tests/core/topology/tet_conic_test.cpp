// The exact degenerate curve of the linear field in one tet (core/topology/tet_conic.h),
// checked against the field evaluated independently: every conic point is a degenerate point of
// the field with the point's eigenvector as the non-repeated eigenvector and σ's sign as its
// L/P type; the chart angle inverts the chart; non-generic fields have no conic.
#include "core/topology/tet_conic.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/design/design_element.h"
#include "tests/core/topology/tet_field_checks.h"

namespace tfd::core::topology {
namespace {

using testing::isolatedEigenvector;
using testing::randomTet;
using testing::relativeGap;
using testing::TetData;

TEST(TetConic, EveryConicPointIsADegeneratePointOfTheField) {
  int checked = 0, linear = 0, planar = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const TetData t = randomTet(rng);
    const TetLinearField field(t.corners, t.tensors);
    const TetConic conic(field);
    ASSERT_TRUE(conic.valid()) << "random fields are generic, seed " << seed;
    for (int i = 0; i < 64; ++i) {
      const double theta = -std::numbers::pi + 2 * std::numbers::pi * (i + 0.5) / 64;
      const ConicPoint p = conic.point(theta);
      EXPECT_LT(conic.residual(p.eigenvector), 1e-12);
      EXPECT_NEAR(std::remainder(conic.theta(p.eigenvector) - theta, 2 * std::numbers::pi), 0,
                  1e-9);
      EXPECT_NEAR(p.eigenvector.norm(), 1, 1e-12);
      if (!p.finite || p.position.norm() > 50) continue;  // far away: too ill-conditioned
      const Tensor a = t.at(p.position);
      ASSERT_LT(relativeGap(a), 1e-7) << "seed " << seed << " θ " << theta;
      const auto iso = isolatedEigenvector(a);
      EXPECT_GT(std::abs(iso.vector.dot(p.eigenvector)), 1 - 1e-8);
      EXPECT_EQ(iso.linear, p.sigma > 0);
      // A = σ b(v) with b(v) = |v|² … : |σ| is the field's size at p in units of the scale.
      EXPECT_GT(std::abs(p.sigma), 0);
      ++checked;
      (p.sigma > 0 ? linear : planar)++;
    }
  }
  EXPECT_GT(checked, 600);
  EXPECT_GT(linear, 50);
  EXPECT_GT(planar, 50);
}

TEST(TetConic, TheDesignedDegenerateLineIsOnTheConic) {
  // A degenerate design element at the origin (paper Eq. 3) makes the origin a degenerate point
  // with the frame's z axis as non-repeated eigenvector: the conic passes through it there.
  // Eq. 3 alone is not generic (its z derivative is zero and Tx, Ty act on the degenerate plane
  // only, so the conic is a line pair): random parts are added to the three derivatives; the
  // origin keeps T0 and so its degeneracy.
  std::mt19937_64 rng(17);
  for (const auto type : {DegenerateType::Linear, DegenerateType::Planar}) {
    const Mat3 frame = rotationFromEulerDegrees(Vec3(10, 20, 30));
    LocalLinearization l =
        makeDegenerateLinearization(Vec3::Zero(), frame, type, DegeneratePattern::Wedge);
    for (auto& j : l.jacobian) j += testing::randomTraceless(rng, 0.3);
    TetData t;
    t.corners = {Vec3(-0.2, -0.2, -0.2), Vec3(0.3, -0.1, -0.1), Vec3(-0.1, 0.3, -0.1),
                 Vec3(-0.1, -0.1, 0.3)};
    for (int i = 0; i < 4; ++i) t.tensors[i] = l.evaluate(t.corners[i]);
    const TetLinearField field(t.corners, t.tensors);
    const TetConic conic(field);
    ASSERT_TRUE(conic.valid());
    const Vec3 e = frame.col(2);
    EXPECT_LT(conic.residual(e), 1e-12);
    const ConicPoint p = conic.point(conic.theta(e));
    ASSERT_TRUE(p.finite);
    EXPECT_LT(p.position.norm(), 1e-10);
    EXPECT_GT(std::abs(p.eigenvector.dot(e)), 1 - 1e-12);
    EXPECT_EQ(p.sigma > 0, type == DegenerateType::Linear);
  }
}

TEST(TetConic, NonGenericFieldsHaveNoConic) {
  std::mt19937_64 rng(7);
  TetData t = randomTet(rng);
  // Constant field: no gradients.
  for (auto& a : t.tensors) a = t.tensors[0];
  EXPECT_FALSE(TetConic(TetLinearField(t.corners, t.tensors)).valid());
  // Zero field.
  for (auto& a : t.tensors) a = Tensor{};
  EXPECT_FALSE(TetConic(TetLinearField(t.corners, t.tensors)).valid());
  // Field varying along x only (span of dimension 2), on a corner tet whose local gradients
  // along y and z come out exactly zero.
  t.corners = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Tensor a0 = testing::randomTraceless(rng), g = testing::randomTraceless(rng);
  for (int i = 0; i < 4; ++i) t.tensors[i] = a0 + t.corners[i].x() * g;
  EXPECT_FALSE(TetConic(TetLinearField(t.corners, t.tensors)).valid());
}

TEST(TetConic, LinearFieldIsReproducedInLocalCoordinates) {
  std::mt19937_64 rng(11);
  const TetData t = randomTet(rng);
  const TetLinearField f(t.corners, t.tensors);
  const Vec3 p(0.3, 0.2, 0.25);
  const Vec3 q = f.local(p);
  Vec5 v = f.value;
  for (int k = 0; k < 3; ++k) v += q[k] * f.gradient[k];
  EXPECT_LT((v * f.scale - toVec5(t.at(p))).norm(), 1e-12);
  const Eigen::Vector4d b = f.barycentric(p), ref = t.barycentric(p);
  EXPECT_LT((b - ref).norm(), 1e-12);
}

}  // namespace
}  // namespace tfd::core::topology
