#include "apps/tfd/console_reporter.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace tfd::cli {

ConsoleReporter::Mode ConsoleReporter::detect(bool quiet) {
  if (quiet) return Mode::Quiet;
  return isatty(fileno(stderr)) ? Mode::Bar : Mode::Lines;
}

void ConsoleReporter::cookStarted(std::size_t requested, std::size_t) {
  std::lock_guard lock(mutex_);
  total_ = requested;
  done_ = 0;
  running_.clear();
  shown_ = 0;
}

void ConsoleReporter::nodeStarted(const std::string& node, const std::string&) {
  if (mode_ != Mode::Bar) return;
  std::lock_guard lock(mutex_);
  current_ = node;
  stage_.clear();
  fraction_ = 0;
  running_[node] = 0;
  drawBar(true);
}

void ConsoleReporter::nodeProgress(const std::string& node, double fraction,
                                   std::string_view stage) {
  if (mode_ != Mode::Bar) return;
  std::lock_guard lock(mutex_);
  current_ = node;
  fraction_ = fraction;
  stage_ = std::string(stage);
  running_[node] = fraction;
  drawBar(false);
}

void ConsoleReporter::nodeFinished(const graph::NodeReport& report) {
  if (mode_ == Mode::Quiet) return;
  std::lock_guard lock(mutex_);
  ++done_;
  running_.erase(report.node);
  if (mode_ == Mode::Bar) {
    drawBar(true);
    return;
  }
  char seconds[32] = "";
  if (report.cookCalled) std::snprintf(seconds, sizeof seconds, " %.3f s", report.seconds);
  std::cerr << "[" << done_ << "/" << total_ << "] " << graph::stateName(report.state) << " "
            << report.node << " (" << report.type << ")" << seconds << "\n";
}

void ConsoleReporter::drawBar(bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  constexpr int kWidth = 28;
  // Finished nodes plus the fractions of those cooking in parallel branches.
  double partial = 0;
  for (const auto& [node, fraction] : running_) partial += fraction;
  const double overall = total_ == 0 ? 1.0 : (static_cast<double>(done_) + partial) / total_;
  shown_ = std::max(shown_, std::min(overall, 1.0));
  const int filled = static_cast<int>(shown_ * kWidth + 0.5);
  std::string bar(filled, '=');
  bar.resize(kWidth, ' ');
  char line[256];
  std::snprintf(line, sizeof line, "\r\033[K[%s] %zu/%zu %s %3.0f%% %s", bar.c_str(), done_, total_,
                current_.c_str(), fraction_ * 100.0, stage_.c_str());
  std::cerr << line << std::flush;
  drawn_ = true;
}

void ConsoleReporter::finish() {
  std::lock_guard lock(mutex_);
  if (drawn_) std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

}  // namespace tfd::cli
