// The optimised 15-axis box overlap test agrees with the plain corner-projection form of the
// separating-axis theorem on random boxes (many of them close to touching), and with hand
// cases whose answer is known.
#include "core/synth/oriented_box.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/core/synth/synth_test_support.h"

namespace tfd::core {
namespace {

Mat3 randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

TEST(OrientedBox, KnownCases) {
  OrientedBox a{Vec3::Zero(), Mat3::Identity(), Vec3(1, 1, 1)};
  OrientedBox b = a;
  b.centre = Vec3(1.99, 0, 0);
  EXPECT_TRUE(boxesOverlap(a, b));
  b.centre = Vec3(2.01, 0, 0);
  EXPECT_FALSE(boxesOverlap(a, b));
  // A cube turned 45° about z reaches √2 along x.
  b.axes = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
  b.centre = Vec3(1 + std::sqrt(2.0) - 0.01, 0, 0);
  EXPECT_TRUE(boxesOverlap(a, b));
  b.centre = Vec3(1 + std::sqrt(2.0) + 0.01, 0, 0);
  EXPECT_FALSE(boxesOverlap(a, b));
  // Two thin sticks crossing like an X: an edge-edge axis case. They cross at the origin when
  // in the same plane, and are separated along z (the edge-edge axis) when lifted apart.
  OrientedBox s{Vec3::Zero(), Mat3::Identity(), Vec3(1, 0.05, 0.05)};
  OrientedBox t = s;
  t.axes = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()).toRotationMatrix();
  t.centre = Vec3(0, 0, 0.09);
  EXPECT_TRUE(boxesOverlap(s, t));
  t.centre = Vec3(0, 0, 0.11);
  EXPECT_FALSE(boxesOverlap(s, t));
  // Skew sticks, neither face-separated: only a cross-product axis separates them.
  t.axes = Eigen::AngleAxisd(M_PI / 3, Vec3::UnitZ()).toRotationMatrix() *
           Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
  t.centre = Vec3(0, 0, 0.2);
  EXPECT_EQ(boxesOverlap(s, t), test::cornersOverlap(s, t));
}

TEST(OrientedBox, AgreesWithCornerProjectionsOnRandomBoxes) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.02, 1.0), c(-1.5, 1.5);
  int overlapping = 0, separate = 0;
  for (int i = 0; i < 20000; ++i) {
    OrientedBox a{Vec3(c(rng), c(rng), c(rng)), randomRotation(rng), Vec3(u(rng), u(rng), u(rng))};
    OrientedBox b{Vec3(c(rng), c(rng), c(rng)), randomRotation(rng), Vec3(u(rng), u(rng), u(rng))};
    if (i % 3 == 0) {  // elongated sticks and flat leaves, as the elements are
      a.half = Vec3(u(rng), 0.03, 0.03);
      b.half = Vec3(u(rng), 0.4 * u(rng), 0.01);
    }
    const bool expected = test::cornersOverlap(a, b);
    ASSERT_EQ(boxesOverlap(a, b), expected) << "pair " << i;
    ASSERT_EQ(boxesOverlap(b, a), expected) << "pair " << i << " swapped";
    (expected ? overlapping : separate)++;
  }
  EXPECT_GT(overlapping, 2000);
  EXPECT_GT(separate, 2000);
}

}  // namespace
}  // namespace tfd::core
