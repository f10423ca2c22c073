#include "apps/tfd/console_reporter.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tfd::cli {

namespace {
double secondsBetween(ConsoleReporter::Clock::time_point a, ConsoleReporter::Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

ConsoleReporter::ConsoleReporter(Mode mode, std::ostream& out, double interval)
    : mode_(mode),
      out_(out),
      interval_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(std::max(interval, 0.01)))) {
  if (mode_ != Mode::Quiet) ticker_ = std::thread([this] { tick(); });
}

ConsoleReporter::~ConsoleReporter() { finish(); }

ConsoleReporter::Mode ConsoleReporter::detect(bool quiet) {
  if (quiet) return Mode::Quiet;
  return isatty(fileno(stderr)) ? Mode::Bar : Mode::Lines;
}

void ConsoleReporter::tick() {
  std::unique_lock lock(mutex_);
  const auto step =
      mode_ == Mode::Bar
          ? std::chrono::milliseconds(100)
          : std::min(std::chrono::duration_cast<Clock::duration>(std::chrono::milliseconds(250)),
                     interval_ / 4);
  while (!stop_) {
    wake_.wait_for(lock, step);
    if (stop_) break;
    const auto now = Clock::now();
    if (mode_ == Mode::Bar) {
      ++spin_;
      if (!running_.empty()) drawBar(true);
      continue;
    }
    for (auto& [node, r] : running_)
      if (now - r.lastLine >= interval_) {
        r.lastLine = now;
        out_ << "... " << describe(node, r, now, true) << "\n" << std::flush;
      }
  }
}

std::string ConsoleReporter::describe(const std::string& node, const Running& r,
                                      Clock::time_point now, bool forLine) const {
  const double elapsed = secondsBetween(r.start, now);
  char text[160];
  std::string out = node + " (" + r.type + ")";
  if (forLine) {
    std::snprintf(text, sizeof text, " running %.0f s", elapsed);
    out += text;
  }
  if (r.fraction > 0) {
    std::snprintf(text, sizeof text, "%s%.0f%%", forLine ? ", " : " ", r.fraction * 100.0);
    out += text;
    if (!r.stage.empty()) out += " " + r.stage;
  }
  if (!forLine) {
    std::snprintf(text, sizeof text, "  %.1f s", elapsed);
    out += text;
  }
  if (live(r, now)) {
    const double rate = (r.fraction - r.firstFraction) / secondsBetween(r.firstReport, now);
    const double left = (1.0 - r.fraction) / rate;
    std::snprintf(text, sizeof text, ", about %.0f s left", std::ceil(left));
    out += text;
  }
  return out;
}

bool ConsoleReporter::live(const Running& r, Clock::time_point now) {
  return r.fraction > r.firstFraction && r.fraction < 1.0 &&
         now - r.lastChange < std::chrono::seconds(3) && now > r.firstReport;
}

void ConsoleReporter::cookStarted(std::size_t requested, std::size_t) {
  std::lock_guard lock(mutex_);
  total_ = requested;
  done_ = 0;
  running_.clear();
  shown_ = 0;
}

void ConsoleReporter::nodeStarted(const std::string& node, const std::string& type) {
  if (mode_ == Mode::Quiet) return;
  std::lock_guard lock(mutex_);
  const auto now = Clock::now();
  Running r;
  r.type = type;
  r.start = r.lastLine = now;
  r.order = ++started_;
  running_[node] = std::move(r);
  if (mode_ == Mode::Lines)
    out_ << "start " << node << " (" << type << ")\n" << std::flush;
  else
    drawBar(true);
}

void ConsoleReporter::nodeProgress(const std::string& node, double fraction,
                                   std::string_view stage) {
  if (mode_ == Mode::Quiet) return;
  std::lock_guard lock(mutex_);
  auto it = running_.find(node);
  if (it == running_.end()) return;
  Running& r = it->second;
  const auto now = Clock::now();
  if (r.firstReport == Clock::time_point{}) {
    r.firstReport = now;
    r.firstFraction = fraction;
  }
  if (fraction != r.fraction) r.lastChange = now;
  r.fraction = fraction;
  r.stage = std::string(stage);
  if (mode_ == Mode::Bar) drawBar(false);
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
  out_ << "[" << done_ << "/" << total_ << "] " << graph::stateName(report.state)
       << (report.fromDisk ? " (disk)" : "") << " " << report.node << " (" << report.type << ")"
       << seconds << "\n"
       << std::flush;
}

void ConsoleReporter::drawBar(bool force) {
  const auto now = Clock::now();
  if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  constexpr int kWidth = 24;
  // Finished nodes plus the fractions of those cooking in parallel branches.
  double partial = 0;
  const std::string* label = nullptr;
  const Running* current = nullptr;
  for (const auto& [node, r] : running_) {
    partial += r.fraction;
    if (!current || r.order > current->order) current = &r, label = &node;
  }
  const double overall = total_ == 0 ? 1.0 : (static_cast<double>(done_) + partial) / total_;
  shown_ = std::max(shown_, std::min(overall, 1.0));
  std::string bar(static_cast<std::size_t>(shown_ * kWidth + 0.5), '=');
  if (current && !live(*current, now) && bar.size() < kWidth)
    bar += "|/-\\"[spin_ % 4];  // the spinner: a step that reports no fraction
  bar.resize(kWidth, ' ');
  std::string what = current ? describe(*label, *current, now, false) : std::string();
  if (running_.size() > 1) what += " (+" + std::to_string(running_.size() - 1) + " running)";
  out_ << "\r\033[K[" << bar << "] " << done_ << "/" << total_ << " " << what << std::flush;
  drawn_ = true;
}

void ConsoleReporter::finish() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  std::lock_guard lock(mutex_);
  if (drawn_) out_ << "\r\033[K" << std::flush;
  drawn_ = false;
}

}  // namespace tfd::cli
