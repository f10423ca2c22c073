// What a primitive's parameters announce is checked against the memory budget before anything
// is built: a torus with major radius 1e9 or minor radius 1e-9 used to run for a minute and end
// in bad_alloc at 5 GB. Now it is refused at once, naming the radii.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/surface/primitives.h"

namespace tfd::core {
namespace {

/// The message of the refusal; fails the test when `spec` is built (or takes long).
std::string refusal(const PrimitiveSpec& spec, double targetTets = 20000) {
  const auto start = std::chrono::steady_clock::now();
  std::string message;
  try {
    makePrimitiveForTets(spec, targetTets);
    ADD_FAILURE() << "built a " << primitiveShapeName(spec.shape);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0)
      << "refused before building";
  return message;
}

class PrimitiveMemory : public ::testing::Test {
 protected:
  void SetUp() override { setMemoryBudget(std::uint64_t(4) << 30); }  // 4 GB, any machine
  void TearDown() override { setMemoryBudget(0); }
};

TEST_F(PrimitiveMemory, AHugeMajorRadiusIsRefusedNamingTheRadii) {
  const std::string m = refusal({.shape = PrimitiveShape::Torus, .majorRadius = 1e9});
  EXPECT_NE(m.find("primitive torus (major radius 1e+09, minor radius 0.4): its surface of about"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("more than the memory budget of 4.0 GB (--max-memory)"), std::string::npos) << m;
}

TEST_F(PrimitiveMemory, ATinyMinorRadiusIsRefusedNamingTheRadii) {
  for (auto shape : {PrimitiveShape::Torus, PrimitiveShape::DoubleTorus}) {
    const std::string m = refusal({.shape = shape, .minorRadius = 1e-9});
    EXPECT_NE(m.find("major radius 1, minor radius 1e-09"), std::string::npos) << m;
    EXPECT_NE(m.find("memory budget"), std::string::npos) << m;
  }
}

TEST_F(PrimitiveMemory, UsualPrimitivesFitAndTheBudgetIsWhatDecides) {
  for (auto shape : {PrimitiveShape::Sphere, PrimitiveShape::Box, PrimitiveShape::Torus,
                     PrimitiveShape::DoubleTorus})
    EXPECT_GT(makePrimitiveForTets({.shape = shape}, 3000).triangles.size(), 100u);
  // The same torus at a million tets needs more than 1 MB of surface.
  setMemoryBudget(std::uint64_t(1) << 20);
  EXPECT_NE(refusal({.shape = PrimitiveShape::Torus}, 1e6).find("(--max-memory)"),
            std::string::npos);
}

TEST_F(PrimitiveMemory, AThinDoubleTorusVolumeIsComputedWithoutARunaway) {
  // The volume integration's cells are bounded: a thin tube gets coarser cells.
  const auto start = std::chrono::steady_clock::now();
  const double v = primitiveVolume(
      {.shape = PrimitiveShape::DoubleTorus, .majorRadius = 1, .minorRadius = 0.01});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  const double twoTori = 2 * 2 * M_PI * M_PI * 1 * 0.01 * 0.01;
  EXPECT_NEAR(v / twoTori, 1.0, 0.1);
}

}  // namespace
}  // namespace tfd::core
