#pragma once
// Shows cooking progress on stderr. Thread-safe (the evaluator calls it from TBB workers).
//
//   Bar (stderr is a terminal): one redrawn line that always names the node running, e.g.
//       [=======>     ] 4/12 field (Propagate) 42% solving  3.1 s, about 4 s left
//       [ |           ] 1/12 ball (TetMesh) 5% TetGen  6.4 s  <- a spinner while a step
//                                                               reports no fraction (TetGen)
//     An estimate of the time left is shown only while the fraction moves (it changed in the
//     last 3 s), from its rate since the node's first report; a step that reports one fraction
//     and then nothing for long (TetGen) gets the spinner instead.
//     redrawn at least every 0.1 s by a ticker thread, so the spinner and the time move even
//     while a node reports nothing.
//   Lines (not a terminal: logs, CI): one line per node start and end and, while a node runs
//     longer, a line every `interval` seconds (default 10):
//       start ball (TetMesh)
//       ... ball (TetMesh) running 10 s
//       ... field (Propagate) running 20 s, 42% solving, about 27 s left
//       [1/12] cooked ball (TetMesh) 12.301 s
//       [2/12] cached (disk) design (MergeConstraints)
//   Quiet: nothing.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <iostream>
#include <map>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "graph/evaluator.h"

namespace tfd::cli {

class ConsoleReporter : public graph::CookObserver {
 public:
  enum class Mode { Quiet, Lines, Bar };
  using Clock = std::chrono::steady_clock;
  /// `interval`: seconds between the periodic lines of a running node (Lines mode).
  explicit ConsoleReporter(Mode mode, std::ostream& out = std::cerr, double interval = 10.0);
  ~ConsoleReporter() override;
  /// Bar when stderr is a terminal, else Lines; Quiet when `quiet`.
  static Mode detect(bool quiet);

  void cookStarted(std::size_t requested, std::size_t cached) override;
  void nodeStarted(const std::string& node, const std::string& type) override;
  void nodeProgress(const std::string& node, double fraction, std::string_view stage) override;
  void nodeFinished(const graph::NodeReport& report) override;
  /// Stops the ticker and clears the bar (call once cooking is over).
  void finish();

 private:
  struct Running {
    std::string type, stage;
    double fraction = 0, firstFraction = 0;
    Clock::time_point start, lastLine, firstReport, lastChange;
    std::uint64_t order = 0;  ///< start order: the label names the latest one
  };
  void tick();
  /// The fraction moved lately: an estimate makes sense.
  static bool live(const Running& r, Clock::time_point now);
  void drawBar(bool force);
  std::string describe(const std::string& node, const Running& r, Clock::time_point now,
                       bool forLine) const;

  Mode mode_;
  std::ostream& out_;
  Clock::duration interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread ticker_;
  std::size_t total_ = 0, done_ = 0;
  std::uint64_t started_ = 0;
  std::map<std::string, Running> running_;
  double shown_ = 0;  ///< overall fraction drawn last (never decreases)
  unsigned spin_ = 0;
  bool drawn_ = false;
  Clock::time_point lastDraw_{};
};

}  // namespace tfd::cli
