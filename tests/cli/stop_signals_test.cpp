// Stopping a cook: SIGTERM cancels like Ctrl-C (exit 143, 130 for SIGINT), also while TetGen
// runs (it runs in a child process the cook kills); a second signal stops at once; nothing is
// left running and no temporary is left behind.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/surface/primitives.h"
#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

extern char** environ;

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// True once `parent` has a child process (TetGen runs in one), polling /proc for up to
/// `limit`. A fixed sleep instead raced the start-up of `tfd` on a loaded machine.
bool waitForChild(pid_t parent, std::chrono::milliseconds limit) {
  const auto deadline = Clock::now() + limit;
  while (Clock::now() < deadline) {
    for (const auto& e : fs::directory_iterator("/proc")) {
      std::ifstream stat(e.path() / "stat");
      std::string line;
      if (!std::getline(stat, line)) continue;
      // pid (comm) state ppid ...: comm may hold spaces, so read after the last ')'.
      const auto close = line.rfind(')');
      if (close == std::string::npos) continue;
      std::istringstream rest(line.substr(close + 1));
      std::string state;
      long ppid = 0;
      if (rest >> state >> ppid && ppid == parent) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A sphere with one vertex far away: TetGen's refinement of it does not end for minutes.
void writeFarVertexSphere(const fs::path& path) {
  core::SurfaceMesh s = core::makeSphere(1, 0.5);
  s.positions[s.positions.size() / 2] *= 1e5;
  std::ofstream out(path);
  out.precision(17);
  for (const auto& p : s.positions) out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : s.triangles)
    out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

class StopSignals : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
    writeFarVertexSphere(dir.path() / "far.obj");
    std::ofstream(dir.path() / "g.tfd.json")
        << R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {"m": {"type": "TetMesh",)"
        << R"( "typeVersion": 1, "params": {"file": "far.obj", "target_tets": 300}}}, "links": []})";
  }

  /// Starts `tfd cook g.tfd.json`, sends `signals` (one after the other, `gap` apart) once it
  /// is inside TetGen, and returns its exit code; `seconds` is the time from the first signal
  /// to the exit.
  int cookAndSignal(const std::vector<int>& signals, double& seconds,
                    std::chrono::milliseconds gap = std::chrono::milliseconds(0)) {
    const std::string graph = (dir.path() / "g.tfd.json").string();
    const std::string err = (dir.path() / "err.txt").string();
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const char* argv[] = {TFD_CLI_PATH, "cook", graph.c_str(), nullptr};
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, TFD_CLI_PATH, &files, nullptr, const_cast<char**>(argv), environ),
              0);
    posix_spawn_file_actions_destroy(&files);
    EXPECT_TRUE(waitForChild(pid, std::chrono::seconds(30))) << "TetGen's child never started";
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // and is inside TetGen
    const auto start = Clock::now();
    for (int s : signals) {
      ::kill(pid, s);
      std::this_thread::sleep_for(gap);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stderrText = slurp(err);
    fs::remove(err);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  }

  TempDir dir{"stop-signals"};
  std::string stderrText;
};

TEST_F(StopSignals, TermCancelsLikeCtrlCEvenInsideTetgen) {
  double seconds = 0;
  EXPECT_EQ(cookAndSignal({SIGTERM}, seconds), 143) << stderrText;
  EXPECT_LT(seconds, 1.0) << "the cook stops TetGen's child process";
  EXPECT_NE(stderrText.find("cancelled m (TetMesh)"), std::string::npos) << stderrText;
  EXPECT_EQ(cookAndSignal({SIGINT}, seconds), 130) << stderrText;
  EXPECT_LT(seconds, 1.0);
  // Nothing but the manifest, which says the cook was cancelled.
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"far.obj", "g.tfd.json", "tfd-cook.json"}));
  EXPECT_NE(slurp(dir.path() / "tfd-cook.json").find("\"status\": \"cancelled\""),
            std::string::npos)
      << slurp(dir.path() / "tfd-cook.json");
}

TEST_F(StopSignals, ASecondSignalStopsAtOnce) {
  double seconds = 0;
  EXPECT_EQ(cookAndSignal({SIGTERM, SIGTERM}, seconds), 143) << stderrText;
  EXPECT_LT(seconds, 1.0);
}

}  // namespace
}  // namespace tfd::test
