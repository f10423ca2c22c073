#include "io/tetgen/tetgen_process.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <tetgen.h>
#include <unistd.h>

#include <fcntl.h>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>

#include "core/error.h"
#include "core/memory_budget.h"

namespace tfd::io {

namespace {

constexpr std::int32_t kMagic = 0x74657467;  // "tetg"

/// What the child sends first; the said text, the points and the tets follow.
struct Header {
  std::int32_t magic = kMagic;
  std::int32_t failureCode = 0;
  std::int64_t points = 0;
  std::int64_t tets = 0;
  std::uint32_t saidBytes = 0;
};

/// TetGen's printout as one line: white space runs collapsed, at most about 300 characters,
/// bytes outside printable ASCII dropped.
std::string flatten(const std::string& text) {
  std::string flat;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isspace(u)) {
      if (!flat.empty() && flat.back() != ' ') flat += ' ';
    } else if (u >= 0x20 && u < 0x7f) {
      flat += c;
    }
  }
  while (!flat.empty() && flat.back() == ' ') flat.pop_back();
  if (flat.size() > 300) flat = flat.substr(0, 300) + "...";
  return flat;
}

bool writeAll(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

/// The child: run TetGen, send the result through `fd` (descriptor 3), exit without running
/// any of the parent's exit handlers.
[[noreturn]] void childMain(int fd, std::string switches, tetgenio& in, pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the process that waits for us
  if (::getppid() != parent) ::_exit(3);
  std::signal(SIGINT, SIG_IGN);  // the parent decides about Ctrl-C and kills us
  std::signal(SIGTERM, SIG_DFL);
  std::signal(SIGPIPE, SIG_DFL);
  if (fd != 3) {
    ::dup2(fd, 3);
    fd = 3;
  }
  ::close_range(4, ~0U, 0);             // nothing of the parent's files (other children's pipes)
  std::FILE* capture = std::tmpfile();  // TetGen prints with printf even with Q
  if (capture) ::dup2(::fileno(capture), STDOUT_FILENO);

  Header header;
  tetgenio out;
  try {
    ::tetrahedralize(switches.data(), &in, &out);
  } catch (int code) {
    header.failureCode = code;
  } catch (const std::bad_alloc&) {
    header.failureCode = 1;
  } catch (...) {
    header.failureCode = 2;
  }
  std::fflush(stdout);
  std::string said;
  if (capture) {
    std::rewind(capture);
    char buffer[4096];
    said.assign(buffer, std::fread(buffer, 1, sizeof buffer, capture));
    said = flatten(said);
  }
  if (header.failureCode == 0) {
    header.points = out.numberofpoints;
    header.tets = out.pointlist && out.tetrahedronlist ? out.numberoftetrahedra : 0;
  }
  header.saidBytes = static_cast<std::uint32_t>(said.size());
  bool ok = writeAll(fd, &header, sizeof header) && writeAll(fd, said.data(), said.size());
  if (ok && header.points > 0)
    ok = writeAll(fd, out.pointlist, sizeof(double) * 3 * std::size_t(header.points));
  const int corners = out.numberofcorners, first = out.firstnumber;
  int chunk[4 * 1024];
  for (std::int64_t t = 0; ok && t < header.tets;) {
    int n = 0;
    for (; n < 1024 && t < header.tets; ++n, ++t)
      for (int i = 0; i < 4; ++i) chunk[4 * n + i] = out.tetrahedronlist[corners * t + i] - first;
    ok = writeAll(fd, chunk, sizeof(int) * 4 * std::size_t(n));
  }
  ::_exit(ok ? 0 : 4);
}

using Clock = std::chrono::steady_clock;

/// Resident memory of process `pid` in bytes (0 when unknown).
std::uint64_t residentBytes(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/statm");
  std::uint64_t size = 0, resident = 0;
  if (!(in >> size >> resident)) return 0;
  return resident * std::uint64_t(::sysconf(_SC_PAGE_SIZE));
}

/// The parent's side: reads the child's output while watching the limits; kills and reaps the
/// child on every way out.
class ChildReader {
 public:
  ChildReader(pid_t pid, int fd, const TetgenRunLimits& limits, const core::Progress& progress)
      : pid_(pid), fd_(fd), limits_(limits), progress_(progress), start_(Clock::now()) {}
  ~ChildReader() {
    ::close(fd_);
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  ChildReader(const ChildReader&) = delete;
  ChildReader& operator=(const ChildReader&) = delete;

  void readExactly(void* data, std::size_t n) {
    char* p = static_cast<char*>(data);
    while (n > 0) {
      pollfd ready{fd_, POLLIN, 0};
      const int rc = ::poll(&ready, 1, 50);
      checkLimits();
      if (rc < 0 && errno != EINTR)
        fail("cannot read TetGen's output: " + std::string(std::strerror(errno)));
      if (rc <= 0) continue;
      const ssize_t k = ::read(fd_, p, n);
      if (k < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (k < 0) fail("cannot read TetGen's output: " + std::string(std::strerror(errno)));
      if (k == 0) childDied();
      p += k;
      n -= static_cast<std::size_t>(k);
    }
  }

  /// Reaps the child after a complete read.
  void finish() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw core::Error(limits_.source + ": " + why);
  }

  void checkLimits() {
    if (progress_.cancelled()) throw core::Cancelled();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (limits_.seconds > 0 && elapsed > limits_.seconds) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", limits_.seconds);
      fail("TetGen did not finish within " + std::string(text) + " s (" + limits_.timeLimitName +
           "); stopped. A surface with a very distant or very small feature can keep its "
           "refinement from ending; otherwise ask for fewer tets or allow more time");
    }
    if (limits_.memoryBytes > 0) {
      const std::uint64_t used = residentBytes(pid_);
      if (used > limits_.memoryBytes)
        fail("TetGen needed more than " + core::formatBytes(double(limits_.memoryBytes)) +
             " of memory (the memory budget, see --max-memory); stopped. Ask for fewer tets");
    }
  }

  [[noreturn]] void childDied() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      fail("TetGen was killed (most likely by the system, out of memory); ask for fewer tets");
    if (WIFSIGNALED(status))
      fail("TetGen crashed (" + std::string(strsignal(WTERMSIG(status))) +
           "); the input surface may be degenerate");
    fail("TetGen stopped without a result (exit status " +
         std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }

  pid_t pid_;
  int fd_;
  const TetgenRunLimits& limits_;
  const core::Progress& progress_;
  Clock::time_point start_;
};

}  // namespace

TetgenRun runTetgenInChild(const std::string& switches, tetgenio& in, const TetgenRunLimits& limits,
                           const core::Progress& progress) {
  progress.throwIfCancelled();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw core::Error(limits.source + ": cannot start TetGen: " + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw core::Error(limits.source + ": cannot start TetGen: " + std::strerror(error));
  }
  if (pid == 0) {
    ::close(fds[0]);
    childMain(fds[1], switches, in, parent);
  }
  ::close(fds[1]);
  ChildReader reader(pid, fds[0], limits, progress);
  Header header;
  reader.readExactly(&header, sizeof header);
  const std::uint64_t budget = core::memoryBudget();
  if (header.magic != kMagic || header.points < 0 || header.tets < 0 ||
      header.tets > std::int64_t(1) << 31 || header.saidBytes > 4096 ||
      double(header.points) * 24 + double(header.tets) * 16 > double(budget))
    throw core::Error(limits.source + ": TetGen's output could not be read (bad header)");
  TetgenRun run;
  run.failureCode = header.failureCode;
  run.said.resize(header.saidBytes);
  reader.readExactly(run.said.data(), run.said.size());
  run.points.resize(std::size_t(header.points) * 3);
  reader.readExactly(run.points.data(), run.points.size() * sizeof(double));
  run.tets.resize(std::size_t(header.tets) * 4);
  reader.readExactly(run.tets.data(), run.tets.size() * sizeof(int));
  reader.finish();
  return run;
}

}  // namespace tfd::io
