#include "ui/cook/cook_controller.h"

#include <QMetaObject>
#include <QTimer>

#include <map>
#include <mutex>

namespace tfd::ui {

/// What the worker's observer shares with the UI thread (under the mutex).
struct CookController::Live {
  std::mutex mutex;
  std::size_t toCook = 0, done = 0;
  std::map<std::string, double> running;  ///< node -> fraction
  std::string stage;
  std::atomic<bool> progressPosted{false};
};

/// Runs on TBB worker threads: records, then posts events to the controller (queued).
class CookController::Observer : public graph::CookObserver {
 public:
  Observer(CookController* owner, std::shared_ptr<Live> live)
      : owner_(owner), live_(std::move(live)) {}

  void cookStarted(std::size_t requested, std::size_t cached) override {
    std::lock_guard lock(live_->mutex);
    live_->toCook = requested - cached;
  }
  void nodeStarted(const std::string& node, const std::string&) override {
    {
      std::lock_guard lock(live_->mutex);
      live_->running[node] = 0;
    }
    QMetaObject::invokeMethod(
        owner_,
        [o = owner_, node] {
          NodeStatus s = o->statuses_[node];
          s.state = NodeStatus::State::Cooking;
          s.progress = 0;
          o->statuses_[node] = s;
          emit o->statusChanged(QString::fromStdString(node), s);
        },
        Qt::QueuedConnection);
    postProgress();
  }
  void nodeProgress(const std::string& node, double fraction, std::string_view stage) override {
    {
      std::lock_guard lock(live_->mutex);
      live_->running[node] = fraction;
      live_->stage = node + (stage.empty() ? "" : ": " + std::string(stage));
    }
    postProgress();
  }
  void nodeFinished(const graph::NodeReport& report) override {
    {
      std::lock_guard lock(live_->mutex);
      if (live_->running.erase(report.node)) ++live_->done;
    }
    NodeStatus s = statusFromReport(report);
    QMetaObject::invokeMethod(
        owner_,
        [o = owner_, node = report.node, s] {
          o->statuses_[node] = s;
          emit o->statusChanged(QString::fromStdString(node), s);
        },
        Qt::QueuedConnection);
    postProgress();
  }

 private:
  /// At most one progress event waits in the queue; it reads the latest state when handled.
  void postProgress() {
    if (live_->progressPosted.exchange(true)) return;
    QMetaObject::invokeMethod(
        owner_, [o = owner_] { o->publishProgress(); }, Qt::QueuedConnection);
  }
  CookController* owner_;
  std::shared_ptr<Live> live_;
};

CookController::CookController(GraphDocument& document, QObject* parent)
    : QObject(parent),
      document_(document),
      evaluator_(std::make_unique<graph::Evaluator>()),
      lastGraph_(std::make_shared<graph::Graph>(document.registry())) {
  connect(&document_, &GraphDocument::aboutToChange, this, [this](int flags) {
    if (flags & (kStructureChanged | kParamsChanged | kDocumentReplaced)) cancel();
  });
  connect(&document_, &GraphDocument::changed, this, [this](int flags) {
    if (autoCook_ && (flags & (kStructureChanged | kParamsChanged | kDocumentReplaced)))
      requestCook();
  });
}

CookController::~CookController() {
  cancel_ = true;
  if (worker_.joinable()) worker_.join();
}

void CookController::setAutoCook(bool on) {
  autoCook_ = on;
  if (on) requestCook();
}

void CookController::cancel() {
  if (isCooking()) cancel_ = true;
}

void CookController::requestCook() {
  pending_ = true;
  if (isCooking() || scheduled_) return;
  scheduled_ = true;
  // Coalesce the edits of one event-loop turn (e.g. an undo macro) into one cook.
  QTimer::singleShot(0, this, [this] {
    scheduled_ = false;
    if (pending_ && !isCooking()) start(std::exchange(pendingWithSinks_, false));
  });
}

void CookController::writeOutputs() {
  pendingWithSinks_ = true;
  requestCook();
}

void CookController::start(bool withSinks) {
  pending_ = false;
  cancel_ = false;
  auto snapshot = std::make_shared<graph::Graph>(document_.graph());
  graph::CookOptions options;
  for (const graph::Node& n : snapshot->nodes())
    if (withSinks || !n.decl().isSink()) options.targets.push_back(n.name());
  options.cancel = &cancel_;
  live_ = std::make_shared<Live>();
  observer_ = std::make_unique<Observer>(this, live_);
  options.observer = observer_.get();
  progress_ = 0;
  emit cookStarted();
  emit progressChanged(0, {});
  if (options.targets.empty()) {
    finish(graph::CookResult{}, snapshot);
    return;
  }
  worker_ = std::thread([this, snapshot, options] {
    graph::CookResult result;
    try {
      result = evaluator_->cook(*snapshot, options);
    } catch (const std::exception&) {
      // A target vanished cannot happen with a snapshot; anything else is per node.
      result.cancelled = true;
    }
    QMetaObject::invokeMethod(
        this, [this, r = std::move(result), snapshot]() mutable { finish(std::move(r), snapshot); },
        Qt::QueuedConnection);
  });
}

void CookController::publishProgress() {
  if (!live_) return;
  double fraction = 0;
  QString stage;
  {
    std::lock_guard lock(live_->mutex);
    live_->progressPosted = false;
    double sum = static_cast<double>(live_->done);
    for (const auto& [node, f] : live_->running) sum += std::clamp(f, 0.0, 1.0);
    fraction = live_->toCook ? sum / static_cast<double>(live_->toCook) : 1.0;
    stage = QString::fromStdString(live_->stage);
    for (const auto& [node, f] : live_->running)
      if (auto it = statuses_.find(node); it != statuses_.end() && it->second.progress != f) {
        it->second.progress = f;
        emit statusChanged(QString::fromStdString(node), it->second);
      }
  }
  progress_ = std::max(progress_, std::min(fraction, 1.0));  // never moves backwards
  if (isCooking()) emit progressChanged(progress_, stage);
}

void CookController::finish(graph::CookResult result, std::shared_ptr<graph::Graph> cooked) {
  if (worker_.joinable()) worker_.join();  // the thread has posted this as its last act
  observer_.reset();
  result_ = std::move(result);
  lastGraph_ = std::move(cooked);
  NodeStatusMap statuses;
  for (const graph::NodeReport& r : result_.reports) statuses[r.node] = statusFromReport(r);
  statuses_ = std::move(statuses);
  progress_ = 1;
  ++finished_;
  emit progressChanged(1, {});
  emit cookFinished(result_.cancelled);
  if (pending_) requestCook();
}

}  // namespace tfd::ui
