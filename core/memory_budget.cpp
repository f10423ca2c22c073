#include "core/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace tfd::core {

namespace {

std::atomic<std::uint64_t> gExplicitBudget{0};

/// MemAvailable (bytes) from /proc/meminfo; physical memory when it cannot be read.
std::uint64_t machineAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uint64_t kb = 0;
  std::string unit;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return kb * 1024;
  }
  const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && size > 0) return std::uint64_t(pages) * std::uint64_t(size);
  return std::uint64_t(4) << 30;
}

}  // namespace

std::uint64_t memoryBudget() {
  if (const std::uint64_t set = gExplicitBudget.load(); set != 0) return set;
  std::uint64_t budget = machineAvailable();
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    budget = std::min<std::uint64_t>(budget, limit.rlim_cur);
  return budget;
}

void setMemoryBudget(std::uint64_t bytes) { gExplicitBudget.store(bytes); }

bool memoryBudgetIsExplicit() { return gExplicitBudget.load() != 0; }

void checkMemory(double bytes, const std::string& what) {
  const std::uint64_t budget = memoryBudget();
  if (!(bytes <= double(budget))) {  // also NaN and infinity
    throw Error(what + " needs about " + formatBytes(bytes) + ", more than the memory budget of " +
                formatBytes(double(budget)) +
                (memoryBudgetIsExplicit() ? " (--max-memory)"
                                          : " (the memory available now; see --max-memory)"));
  }
}

std::string formatBytes(double bytes) {
  if (!std::isfinite(bytes)) return "an unbounded amount of memory";
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1024 && u < 6) {
    bytes /= 1024;
    ++u;
  }
  if (u >= 6 && bytes >= 1024) return "more than 1024 EB";
  char text[32];
  std::snprintf(text, sizeof text,
                u == 0       ? "%.0f %s"
                : bytes < 10 ? "%.1f %s"
                             : "%.0f %s",
                bytes, units[u]);
  return text;
}

std::uint64_t parseByteSize(const std::string& text) {
  std::size_t end = 0;
  double value = 0;
  try {
    value = std::stod(text, &end);
  } catch (const std::exception&) {
    end = 0;
  }
  std::string unit = text.substr(end);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() == 2 && unit[1] == 'B') unit.pop_back();
  double scale = 0;
  if (unit.empty() || unit == "B") scale = 1;
  if (unit == "K") scale = 1024.0;
  if (unit == "M") scale = 1024.0 * 1024;
  if (unit == "G") scale = 1024.0 * 1024 * 1024;
  if (unit == "T") scale = 1024.0 * 1024 * 1024 * 1024;
  const double bytes = value * scale;
  if (end == 0 || scale == 0 || !(bytes >= 1024.0 * 1024) || !(bytes < 1e19)) {
    throw Error("expected a memory size of at least 1M such as 512M, 8G or 2.5G, found \"" + text +
                "\"");
  }
  return std::uint64_t(bytes);
}

namespace {
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

/// Bytes of address space mapped now (/proc/self/statm, first field); 0 when unknown.
std::uint64_t mappedBytes() {
  std::ifstream in("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(in >> pages)) return 0;
  return pages * std::uint64_t(::sysconf(_SC_PAGE_SIZE));
}
}  // namespace

AddressSpaceCap::AddressSpaceCap(std::uint64_t bytes) {
  if (kAddressSanitizer) return;
  rlimit limit{};
  const std::uint64_t mapped = mappedBytes();
  if (mapped == 0 || ::getrlimit(RLIMIT_AS, &limit) != 0) return;
  const std::uint64_t cap = mapped + (bytes != 0 ? bytes : memoryBudget());
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= cap) return;
  previous_ = limit.rlim_cur;
  limit.rlim_cur = cap;
  active_ = ::setrlimit(RLIMIT_AS, &limit) == 0;
}

AddressSpaceCap::~AddressSpaceCap() {
  if (!active_) return;
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0) return;
  limit.rlim_cur = previous_;
  ::setrlimit(RLIMIT_AS, &limit);
}

}  // namespace tfd::core
