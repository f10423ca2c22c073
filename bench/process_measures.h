#pragma once
// What a benchmark reads off its own process: the peak resident memory and the kernel's side
// of a run (page faults and system time). Header-only, for the benchmarks in bench/.
#include <sys/resource.h>

#include <fstream>
#include <string>

namespace tfd::bench {

/// Peak resident set size of the process in MB (VmHWM of /proc/self/status; 0 when unknown).
inline double peakMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024;
  return 0;
}

/// The kernel's side of a cook: page faults (each a fresh page the kernel zeroes, and on this
/// kind of virtual machine one the host may have to back again) and system time.
struct MemoryGrowth {
  double pageFaults = 0, systemSeconds = 0;
  static MemoryGrowth now() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return {double(usage.ru_minflt + usage.ru_majflt),
            double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec)};
  }
  MemoryGrowth operator-(const MemoryGrowth& o) const {
    return {pageFaults - o.pageFaults, systemSeconds - o.systemSeconds};
  }
  MemoryGrowth& operator+=(const MemoryGrowth& o) {
    pageFaults += o.pageFaults, systemSeconds += o.systemSeconds;
    return *this;
  }
};

}  // namespace tfd::bench
