// The jittered test meshes are the same with every compiler: the tests designed on them (the
// reconnection scenarios, the removal fields) passed with GCC and failed with Clang's sanitizer
// build, whose meshes differed (tests/support/random_vec3.h).
#include <gtest/gtest.h>

#include <random>

#include "tests/core/design/curve_test_meshes.h"
#include "tests/support/random_vec3.h"

namespace tfd::core {
namespace {

TEST(TestMeshes, DrawVec3DrawsZThenYThenX) {
  std::mt19937 a(5), b(5);
  std::uniform_real_distribution<double> u(-1, 1), v(-1, 1);
  const Vec3 d = test::drawVec3(u, a);
  const double z = v(b), y = v(b), x = v(b);
  EXPECT_EQ(d, Vec3(x, y, z));
}

TEST(TestMeshes, TheJitteredBoxIsTheOneTheTestsWereDesignedOn) {
  // Two interior vertices of jitteredBox(18, 0.15), exactly (hexadecimal floats).
  const auto box = testing::jitteredBox(18, 0.15);
  EXPECT_EQ(box->positions()[381],
            Vec3(-0x1.cd686c7887e4p-1, -0x1.c9b3052a03b82p-1, -0x1.ca9981e8bba25p-1));
  EXPECT_EQ(box->positions()[3000],
            Vec3(0x1.c59f3e44da5ap-1, -0x1.c35fd591b4801p-2, -0x1.b3f1c5e6fb8e2p-4));
}

}  // namespace
}  // namespace tfd::core
