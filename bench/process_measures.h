#pragma once
// What a benchmark reads off its own process: the peak resident memory and, per timed cook,
// the CPU time of all threads and the kernel's side (page faults and system time).
// Header-only, for the benchmarks in bench/.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <ctime>
#include <fstream>
#include <string>

namespace tfd::bench {

/// Resets the peak resident set size of the process (Linux: "5" > /proc/self/clear_refs), so
/// that peakMegabytes() measures from here.
inline void resetPeakMemory() { std::ofstream("/proc/self/clear_refs") << "5"; }

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

/// Sums, over the cooks of a benchmark, the CPU time of all threads (on a loaded machine an
/// upper bound for a quiet one's wall time) and the kernel's side. Each repetition's body
/// holds a Cook for its duration; report() sets the counters cpu_all_threads_s, system_s and
/// page_faults.
class CookCounters {
 public:
  class Cook {
   public:
    explicit Cook(CookCounters& sum) : sum_(sum) {}
    ~Cook() {
      sum_.growth_ += MemoryGrowth::now() - growth_;
      sum_.cpu_ += double(std::clock() - cpu_) / CLOCKS_PER_SEC;
    }
    Cook(const Cook&) = delete;
    Cook& operator=(const Cook&) = delete;

   private:
    CookCounters& sum_;
    const std::clock_t cpu_ = std::clock();
    const MemoryGrowth growth_ = MemoryGrowth::now();
  };

  void report(benchmark::State& state) const {
    state.counters["cpu_all_threads_s"] = cpu_;
    state.counters["system_s"] = growth_.systemSeconds;
    state.counters["page_faults"] = growth_.pageFaults;
  }

 private:
  double cpu_ = 0;
  MemoryGrowth growth_;
};

}  // namespace tfd::bench
