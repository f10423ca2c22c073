#include "core/tensor.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace tfd::core {
namespace {

Tensor randomSymmetric(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  return {n(rng), n(rng), n(rng), n(rng), n(rng), n(rng)};
}

/// Random tensor with chosen eigenvalues in a random rotation.
Tensor withEigenvalues(std::mt19937_64& rng, const Vec3& values) {
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(Eigen::Vector4d(randomSymmetric(rng).components().data())).normalized();
  const Mat3 r = q.toRotationMatrix();
  return Tensor::fromMatrix(r * values.asDiagonal() * r.transpose());
}

void expectGoodDecomposition(const Tensor& t) {
  const EigenDecomposition e = eigenDecompose(t);
  const Mat3 m = t.matrix();
  const double scale = std::max(m.norm(), 1e-300);
  ASSERT_GE(e.values[0], e.values[1]);
  ASSERT_GE(e.values[1], e.values[2]);
  for (int i = 0; i < 3; ++i) {
    const Vec3 v = e.vectors.col(i);
    ASSERT_LE((m * v - e.values[i] * v).norm(), 1e-9 * scale) << "eigenpair " << i;
  }
  ASSERT_LE((e.vectors.transpose() * e.vectors - Mat3::Identity()).norm(), 1e-12);
  ASSERT_NEAR(e.vectors.determinant(), 1.0, 1e-12);
  // Agreement with an independent (iterative, QR-based) solver.
  Eigen::SelfAdjointEigenSolver<Mat3> reference(m);
  for (int i = 0; i < 3; ++i) {
    ASSERT_NEAR(e.values[i], reference.eigenvalues()[2 - i], 1e-12 * scale);
  }
}

TEST(Tensor, EigenDecompositionOfRandomAndNearDegenerateTensors) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 100000; ++i) {
    Tensor t;
    switch (i % 5) {
      case 0: t = randomSymmetric(rng); break;
      case 1: {  // nearly linear-degenerate
        const double gap = std::pow(10.0, -16 * std::abs(u(rng)));
        t = withEigenvalues(rng, Vec3(2, -1 + gap, -1));
        break;
      }
      case 2: {  // nearly planar-degenerate
        const double gap = std::pow(10.0, -16 * std::abs(u(rng)));
        t = withEigenvalues(rng, Vec3(1, 1 - gap, -2));
        break;
      }
      case 3:  // nearly triple-degenerate, far from zero
        t = withEigenvalues(rng, Vec3(3 + 1e-9 * u(rng), 3 + 1e-9 * u(rng), 3));
        break;
      default:  // exact degeneracies and extreme scales
        t = withEigenvalues(rng, Vec3(u(rng), 0.5, 0.5)) * std::pow(10.0, 100 * u(rng));
    }
    expectGoodDecomposition(t);
  }
}

TEST(Tensor, ZeroAndIdentityHaveOrthonormalFrames) {
  expectGoodDecomposition(Tensor{});
  expectGoodDecomposition(Tensor{1, 1, 1, 0, 0, 0});
}

TEST(Tensor, ClassificationBySignOfMiddleEigenvalue) {
  EXPECT_EQ(classify(Tensor{2, -1, -1, 0, 0, 0}), TensorType::Linear);
  EXPECT_EQ(classify(Tensor{1, 1, -2, 0, 0, 0}), TensorType::Planar);
  EXPECT_EQ(classify(Tensor{1, 0, -1, 0, 0, 0}), TensorType::Neutral);
  // The trace does not matter.
  EXPECT_EQ(classify(Tensor{12, 9, 9, 0, 0, 0}), TensorType::Linear);
}

TEST(Tensor, DiscriminantAndModeMeasureDegeneracy) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Tensor a = randomSymmetric(rng).deviator();
    const Vec3 l = eigenDecompose(a).values;
    const double d = std::pow((l[0] - l[1]) * (l[1] - l[2]) * (l[2] - l[0]), 2);
    EXPECT_NEAR(discriminant(a), d, 1e-10 * std::pow(a.norm(), 6));
    const double m = mode(a);
    EXPECT_NEAR(normalizedDiscriminant(a), 0.5 * (1 - m * m), 1e-10);
  }
  EXPECT_NEAR(mode(Tensor{2, -1, -1, 0, 0, 0}), 1.0, 1e-14);
  EXPECT_NEAR(mode(Tensor{1, 1, -2, 0, 0, 0}), -1.0, 1e-14);
}

TEST(Tensor, Vec5IsAnIsometryOfTracelessTensors) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100; ++i) {
    const Tensor a = randomSymmetric(rng).deviator(), b = randomSymmetric(rng).deviator();
    const auto va = a.vec5(), vb = b.vec5();
    double dot = 0;
    for (int k = 0; k < 5; ++k) dot += va[k] * vb[k];
    EXPECT_NEAR(dot, (a.matrix().cwiseProduct(b.matrix())).sum(), 1e-12);
    const Tensor back = Tensor::fromVec5(va);
    EXPECT_NEAR((back - a).norm(), 0, 1e-14);
  }
}

}  // namespace
}  // namespace tfd::core
