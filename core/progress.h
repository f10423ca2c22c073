#pragma once
// Progress reporting and cooperative cancellation for long computations.
#include <atomic>
#include <functional>
#include <string_view>

#include "core/error.h"

namespace tfd::core {

/// Passed by reference into long computations. They call `report` from the calling thread
/// (never from worker threads) and `throwIfCancelled` inside long loops (worker threads may
/// call `cancelled()`, which only reads an atomic flag).
class Progress {
 public:
  using Callback = std::function<void(double fraction, std::string_view stage)>;

  Progress() = default;
  Progress(Callback callback, const std::atomic<bool>* cancelFlag)
      : callback_(std::move(callback)), cancelFlag_(cancelFlag) {}

  void report(double fraction, std::string_view stage = {}) const {
    if (callback_) callback_(fraction, stage);
  }
  bool cancelled() const {
    return cancelFlag_ != nullptr && cancelFlag_->load(std::memory_order_relaxed);
  }
  void throwIfCancelled() const {
    if (cancelled()) throw Cancelled();
  }

 private:
  Callback callback_;
  const std::atomic<bool>* cancelFlag_ = nullptr;
};

}  // namespace tfd::core
