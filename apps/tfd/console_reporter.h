#pragma once
// Shows cooking progress on stderr: a redrawn progress bar when stderr is a terminal, one
// plain line per finished node otherwise, nothing with --quiet. Thread-safe (the evaluator
// calls it from TBB workers).
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>

#include "graph/evaluator.h"

namespace tfd::cli {

class ConsoleReporter : public graph::CookObserver {
 public:
  enum class Mode { Quiet, Lines, Bar };
  explicit ConsoleReporter(Mode mode) : mode_(mode) {}
  /// Bar when stderr is a terminal, else Lines; Quiet when `quiet`.
  static Mode detect(bool quiet);

  void cookStarted(std::size_t requested, std::size_t cached) override;
  void nodeStarted(const std::string& node, const std::string& type) override;
  void nodeProgress(const std::string& node, double fraction, std::string_view stage) override;
  void nodeFinished(const graph::NodeReport& report) override;
  /// Clears the bar (call once cooking is over).
  void finish();

 private:
  void drawBar(bool force);
  Mode mode_;
  std::mutex mutex_;
  std::size_t total_ = 0, done_ = 0;
  std::string current_, stage_;
  double fraction_ = 0;
  std::map<std::string, double> running_;  ///< fraction of every node cooking now
  double shown_ = 0;                       ///< overall fraction drawn last (never decreases)
  bool drawn_ = false;
  std::chrono::steady_clock::time_point lastDraw_{};
};

}  // namespace tfd::cli
