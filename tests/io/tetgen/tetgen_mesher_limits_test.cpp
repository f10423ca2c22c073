// TetGen where it can be stopped: a surface whose refinement never ends fails within the time
// limit, a cancel reaches TetGen quickly, a request beyond the memory budget is refused before
// meshing, and meshes made at the same time (each TetGen in its own child process) equal
// those made one after the other.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/surface/primitives.h"
#include "io/tetgen/tetgen_mesher.h"

namespace tfd::io {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A coarse sphere with one vertex moved 1e5 radii away: a closed, valid surface on which
/// TetGen's quality refinement (boundary refined, 300 tets wanted) runs for minutes.
core::SurfaceMesh farVertexSphere() {
  core::SurfaceMesh s = core::makeSphere(1, 0.5);
  s.positions[s.positions.size() / 2] *= 1e5;
  return s;
}

TetgenOptions hangingOptions(double timeLimit) {
  TetgenOptions o;
  o.targetTets = 300;
  o.keepBoundary = false;
  o.volumeFactor = 2.5;
  o.timeLimit = timeLimit;
  o.source = "file 'far.obj'";
  return o;
}

/// Child processes of this process that are still around (zombies included).
int childProcesses() {
  int count = 0;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(task.path() / "children");
    for (long pid; in >> pid;) ++count;
  }
  return count;
}

TEST(TetgenLimits, NeverEndingRefinementFailsWithinTheTimeLimit) {
  const auto start = Clock::now();
  try {
    tetrahedralize(farVertexSphere(), hangingOptions(1.5));
    FAIL() << "TetGen finished; this surface no longer hangs it, pick another";
  } catch (const core::Cancelled&) {
    FAIL() << "not cancelled";
  } catch (const core::Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("file 'far.obj': TetGen did not finish within 1.5 s (the time limit)", 0), 0u)
        << m;
  }
  EXPECT_LT(secondsSince(start), 4.0);
  EXPECT_EQ(childProcesses(), 0) << "the child is killed and reaped";
}

TEST(TetgenLimits, CancelReachesTetgenQuickly) {
  std::atomic<bool> cancel{false};
  const core::Progress progress({}, &cancel);
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    cancel = true;
  });
  const auto start = Clock::now();
  EXPECT_THROW(tetrahedralize(farVertexSphere(), hangingOptions(600), progress), core::Cancelled);
  const double seconds = secondsSince(start);
  canceller.join();
  EXPECT_LT(seconds, 1.3) << "cancel must reach inside TetGen";
  EXPECT_EQ(childProcesses(), 0);
}

TEST(TetgenLimits, RequestBeyondTheMemoryBudgetIsRefusedBeforeMeshing) {
  core::setMemoryBudget(std::uint64_t(256) << 20);
  TetgenOptions o;
  o.targetTets = 5e6;
  const auto start = Clock::now();
  try {
    tetrahedralize(core::makeSphere(1, 0.3), o);
    ADD_FAILURE() << "meshed beyond the budget";
  } catch (const core::Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("TetGen for about 5000000 tets needs about 1."), std::string::npos) << m;
    EXPECT_NE(m.find("more than the memory budget of 256 MB (--max-memory)"), std::string::npos)
        << m;
  }
  core::setMemoryBudget(0);
  EXPECT_LT(secondsSince(start), 0.5) << "refused before TetGen starts";
}

TEST(TetgenLimits, MeshesMadeAtTheSameTimeEqualMeshesMadeInTurn) {
  const core::SurfaceMesh a = core::makeSphere(1, 0.15), b = core::makeBox({2, 1, 1}, 0.2);
  TetgenOptions o;
  o.targetTets = 6000;
  const auto aAlone = tetrahedralize(a, o), bAlone = tetrahedralize(b, o);
  std::shared_ptr<const core::TetMesh> aTogether, bTogether;
  // An error in the other thread is carried back: thrown there, it would end the whole test
  // program (std::terminate) instead of failing this test.
  std::exception_ptr otherError;
  std::thread other([&] {
    try {
      bTogether = tetrahedralize(b, o);
    } catch (...) {
      otherError = std::current_exception();
    }
  });
  try {
    aTogether = tetrahedralize(a, o);
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (otherError) std::rethrow_exception(otherError);
  EXPECT_EQ(aTogether->positions(), aAlone->positions());
  EXPECT_EQ(aTogether->tets(), aAlone->tets());
  EXPECT_EQ(bTogether->positions(), bAlone->positions());
  EXPECT_EQ(bTogether->tets(), bAlone->tets());
}

}  // namespace
}  // namespace tfd::io
