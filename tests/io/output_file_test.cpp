// Checked output files, atomic writes and their temporaries: a write cut short by a file-size
// limit is reported naming the target and the old file stays; a folder is refused as a target;
// stale temporaries of dead processes are removed, live ones kept; the signal-time cleanup
// unlinks registered temporaries.
#include "io/output_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/file_bytes.h"
#include "io/temporary_files.h"
#include "tests/support/temp_dir.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `body` in a child process with RLIMIT_FSIZE = `limit` bytes and SIGXFSZ ignored;
/// returns the child's exit code (body's return value), -1 when it died of a signal.
template <class F>
int inChildWithFileLimit(rlim_t limit, F body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit r{limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &r);
    int code = 99;
    try {
      code = body();
    } catch (...) {
      code = 98;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(OutputFile, FileSizeLimitFailsTheWriteNamingTheTargetAndKeepsTheOldFile) {
  test::TempDir dir("output-file-limit");
  const fs::path target = dir.path() / "data.bin";
  io::writeFileBytes(target, "old contents");
  const int code = inChildWithFileLimit(64 * 1024, [&] {
    try {
      io::writeFileBytes(target, std::string(512 * 1024, 'x'));
      return 1;  // success reported for a file that cannot be complete
    } catch (const core::Error& e) {
      const std::string what = e.what();
      if (what.find("'" + target.string() + "'") == std::string::npos) return 2;
      if (what.find("File too large") == std::string::npos) return 3;
      if (what.find(".tfd-tmp") != std::string::npos) return 4;
      return 0;
    }
  });
  EXPECT_EQ(code, 0) << "1: reported success, 2: target not named, 3: no reason, 4: names the "
                        "temporary";
  EXPECT_EQ(bytesOf(target), "old contents");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"data.bin"}) << "no temporary left";
}

TEST(OutputFile, SeekAndTellWriteInPlace) {
  test::TempDir dir("output-file-seek");
  io::writeAtomically(dir.path() / "f.txt", [](io::OutputFile& out) {
    out.stream() << "hello world";
    EXPECT_EQ(out.tell(), 11u);
    ASSERT_TRUE(out.seek(0));
    out.write("J", 1);
    out.stream().seekp(6);
    out.stream() << "W";
  });
  EXPECT_EQ(bytesOf(dir.path() / "f.txt"), "Jello World");
}

TEST(AtomicFile, AFolderIsRefusedAsTargetWithAReason) {
  test::TempDir dir("atomic-folder");
  fs::create_directories(dir.path() / "out");
  for (const fs::path& p : {dir.path() / "out", fs::path(dir.path().string() + "/out/")}) {
    try {
      io::writeFileBytes(p, "x");
      ADD_FAILURE() << "wrote to " << p;
    } catch (const core::Error& e) {
      EXPECT_NE(std::string(e.what()).find("it is a folder, not a file"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_TRUE(fs::is_empty(dir.path() / "out"));
}

TEST(TemporaryFiles, NamesParseBackToTheirTarget) {
  const fs::path temp = io::temporaryPathFor("/x/field.vdb");
  EXPECT_EQ(temp.parent_path(), fs::path("/x"));
  const auto parsed = io::parseTemporaryName(temp.filename().string());
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->target, "field.vdb");
  EXPECT_EQ(parsed->pid, long(::getpid()));
  EXPECT_FALSE(io::parseTemporaryName("field.vdb"));
  EXPECT_FALSE(io::parseTemporaryName(".field.tfd-tmpX-1.vdb"));
  EXPECT_FALSE(io::parseTemporaryName(".field.tfd-tmp12-.vdb"));
}

TEST(TemporaryFiles, StaleTemporariesOfDeadProcessesAreRemovedOnTheNextWrite) {
  test::TempDir dir("atomic-stale");
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);  // reaped: this pid runs no process now
  const std::string deadTemp = ".field.tfd-tmp" + std::to_string(dead) + "-3.vdb";
  const std::string liveTemp = ".field.tfd-tmp" + std::to_string(::getppid()) + "-3.vdb";
  const std::string otherTarget = ".other.tfd-tmp" + std::to_string(dead) + "-3.vdb";
  for (const auto& name : {deadTemp, liveTemp, otherTarget})
    std::ofstream(dir.path() / name) << "partial";
  io::writeFileBytes(dir.path() / "field.vdb", "new");
  const std::vector<std::string> expected{liveTemp, otherTarget, "field.vdb"};
  EXPECT_EQ(dir.entries(), expected);
}

TEST(TemporaryFiles, SignalTimeCleanupUnlinksRegisteredTemporaries) {
  test::TempDir dir("atomic-signal");
  const fs::path temp = dir.path() / ".a.tfd-tmp1-1.txt";
  std::ofstream(temp) << "partial";
  const pid_t pid = ::fork();
  if (pid == 0) {
    io::RegisteredTemporary live(temp);
    io::removeRegisteredTemporaries();
    ::_exit(fs::exists(temp) ? 1 : 0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_FALSE(fs::exists(temp));
}

}  // namespace
}  // namespace tfd
