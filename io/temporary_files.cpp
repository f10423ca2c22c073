#include "io/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

namespace tfd::io {

namespace {

constexpr std::string_view kTag = ".tfd-tmp";

bool allDigits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

/// A process that is gone: kill(pid, 0) says "no such process". (EPERM: alive, someone
/// else's; then the file is left alone.)
bool processGone(long pid) { return pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH; }

// The live registry. A slot holds a malloc'ed path or nullptr. The signal handler sets
// gInSignal before it reads any slot; an unregistering thread clears its slot before it reads
// gInSignal and then frees the string only when no handler runs. With sequentially consistent
// atomics a handler therefore never reads a freed string (either it saw the slot cleared, or
// the thread sees gInSignal set and leaks the string: the process is exiting anyway).
constexpr int kSlots = 4096;
std::array<std::atomic<char*>, kSlots> gSlots{};
std::atomic<bool> gInSignal{false};

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = target;
  temp.replace_filename("." + target.stem().string() + std::string(kTag) +
                        std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                        target.extension().string());
  return temp;
}

std::optional<TemporaryName> parseTemporaryName(std::string_view name) {
  if (name.size() < 2 || name[0] != '.') return std::nullopt;
  const std::size_t tag = name.rfind(kTag);
  if (tag == std::string_view::npos || tag < 1) return std::nullopt;
  std::string_view rest = name.substr(tag + kTag.size());  // <pid>-<n><ext>
  const std::size_t dash = rest.find('-');
  if (dash == std::string_view::npos || !allDigits(rest.substr(0, dash))) return std::nullopt;
  std::size_t n = dash + 1;
  while (n < rest.size() && std::isdigit(static_cast<unsigned char>(rest[n]))) ++n;
  if (n == dash + 1) return std::nullopt;
  const std::string_view extension = rest.substr(n);
  if (!extension.empty() && extension[0] != '.') return std::nullopt;
  TemporaryName out;
  out.target = std::string(name.substr(1, tag - 1)) + std::string(extension);
  const std::string pid(rest.substr(0, dash));
  if (pid.size() > 9) return std::nullopt;
  out.pid = std::strtol(pid.c_str(), nullptr, 10);
  return out;
}

int removeStaleTemporaries(const std::filesystem::path& folder,
                           const std::function<bool(const std::string&)>& belongs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path dir = folder.empty() ? fs::path(".") : folder;
  fs::directory_iterator it(dir, ec), end;
  int removed = 0;
  const long self = ::getpid();
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const auto temp = parseTemporaryName(name);
    if (!temp || temp->pid == self || !belongs(temp->target) || !processGone(temp->pid)) continue;
    std::error_code removeError;
    if (it->is_regular_file(removeError) && fs::remove(it->path(), removeError)) ++removed;
  }
  return removed;
}

RegisteredTemporary::RegisteredTemporary(const std::filesystem::path& path) {
  char* copy = ::strdup(path.c_str());
  if (!copy) return;
  for (int i = 0; i < kSlots; ++i) {
    char* expected = nullptr;
    if (gSlots[i].compare_exchange_strong(expected, copy)) {
      slot_ = i;
      return;
    }
  }
  std::free(copy);
}

RegisteredTemporary::~RegisteredTemporary() {
  if (slot_ < 0) return;
  char* p = gSlots[slot_].exchange(nullptr);
  if (!gInSignal.load()) std::free(p);
}

void removeRegisteredTemporaries() noexcept {
  gInSignal.store(true);
  for (auto& slot : gSlots) {
    if (char* p = slot.load()) ::unlink(p);
  }
}

}  // namespace tfd::io
