#pragma once
// How much memory one computation may plan to use. Large requests (a tet count, a voxel grid,
// what a file announces) are checked against it before anything is allocated, so a small
// input cannot make the process grow until the kernel kills it.
#include <cstdint>
#include <string>

namespace tfd::core {

/// The budget in bytes: the value set with setMemoryBudget (`tfd --max-memory`), otherwise
/// the memory the machine has available now (MemAvailable in /proc/meminfo), bounded by the
/// address-space limit (ulimit -v) when one is set.
std::uint64_t memoryBudget();

/// Sets the budget; 0 returns to the machine default. Thread-safe.
void setMemoryBudget(std::uint64_t bytes);

/// True when the budget was set explicitly (not the machine default).
bool memoryBudgetIsExplicit();

/// Throws core::Error "<what> needs about <bytes>, more than the memory budget of <budget>
/// (...)" when `bytes` (an estimate; may be huge or infinite) exceeds memoryBudget().
void checkMemory(double bytes, const std::string& what);

/// "1.5 GB", "320 MB", "12 KB", "512 bytes".
std::string formatBytes(double bytes);

/// Parses "2G", "512M", "1.5GB", "800000000" (bytes; K/M/G/T are powers of 1024). Throws
/// core::Error for anything else or a value below 1 MB.
std::uint64_t parseByteSize(const std::string& text);

/// For one-shot readers of untrusted files (`tfd info`): caps the process's address space
/// (RLIMIT_AS, as `ulimit -v`) at what it maps now plus memoryBudget(), for this object's
/// lifetime, so that an allocation a damaged file makes a library attempt (OpenVDB, OpenEXR)
/// fails with std::bad_alloc instead of growing until the kernel kills the process. Does
/// nothing under AddressSanitizer (it reserves its shadow memory up front) or when a lower
/// limit is already set. Not for cooks: their threads share the one limit.
class AddressSpaceCap {
 public:
  /// `bytes` above what is mapped now; 0: memoryBudget().
  explicit AddressSpaceCap(std::uint64_t bytes = 0);
  ~AddressSpaceCap();
  AddressSpaceCap(const AddressSpaceCap&) = delete;
  AddressSpaceCap& operator=(const AddressSpaceCap&) = delete;
  bool active() const { return active_; }

 private:
  bool active_ = false;
  std::uint64_t previous_ = 0;
};

}  // namespace tfd::core
