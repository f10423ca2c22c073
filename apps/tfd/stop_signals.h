#pragma once
// SIGINT (Ctrl-C), SIGTERM and SIGHUP during a cook: the first one cancels the cook, which then
// ends cleanly (nodes stop at their next cancellation check, writers remove their temporaries)
// and tfd exits with 128 + the signal number (130, 143, 129). A second one stops at once:
// the handler unlinks the temporaries being written (io::removeRegisteredTemporaries) and
// exits with the same code. SIGKILL cannot be caught: what it leaves is removed by a later
// write of the same target (io/temporary_files.h).
#include <atomic>

namespace tfd::cli {

/// Installs the handlers for its lifetime (restoring the previous ones afterwards).
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// Set by the first signal: pass to graph::CookOptions::cancel.
  static std::atomic<bool>& cancelFlag();
  /// The first signal received, 0 when none.
  static int received();
};

}  // namespace tfd::cli
