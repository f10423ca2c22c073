#include "apps/tfd/stop_signals.h"

#include <unistd.h>

#include <csignal>

#include "io/temporary_files.h"

namespace tfd::cli {

namespace {

std::atomic<bool> gCancel{false};
std::atomic<int> gSignal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "used from a signal handler");

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction gPrevious[3];

extern "C" void onStopSignal(int signal) {
  int expected = 0;
  if (!gSignal.compare_exchange_strong(expected, signal)) {  // the second one: stop at once
    io::removeRegisteredTemporaries();
    _exit(128 + gSignal.load());
  }
  gCancel.store(true);
  const char interrupt[] = "\ntfd: cancelling (press Ctrl-C again to stop at once)\n";
  const char other[] = "\ntfd: stopping on a signal: cancelling and removing temporaries\n";
  [[maybe_unused]] auto n = signal == SIGINT ? write(STDERR_FILENO, interrupt, sizeof interrupt - 1)
                                             : write(STDERR_FILENO, other, sizeof other - 1);
}

}  // namespace

StopSignals::StopSignals() {
  gCancel = false;
  gSignal = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &gPrevious[i]);
}

StopSignals::~StopSignals() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &gPrevious[i], nullptr);
}

std::atomic<bool>& StopSignals::cancelFlag() { return gCancel; }

int StopSignals::received() { return gSignal.load(); }

}  // namespace tfd::cli
