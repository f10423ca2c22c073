#pragma once
// Background cooking for the editor. A worker thread owns each cook: it cooks a snapshot (a
// copy) of the document's graph with a long-lived Evaluator, whose cache makes a re-cook after
// an edit compute only what lies downstream of it. The UI thread never waits on a cook: it
// starts one, gets progress, per-node states and the result as queued events, and cancels by
// setting a flag. Engine code never touches the Qt event loop (the observer only posts events).
//
// Automatic cooking: every edit that changes what is cooked (nodes, links, parameters) cancels
// the running cook before the document changes (aboutToChange), then a new cook starts as soon
// as the cancelled one has stopped. Positions and the display flag do not cancel anything. The
// automatic cook computes every node with outputs; exporters (sinks, which write files) run
// only on writeOutputs().
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <thread>

#include "graph/evaluator.h"
#include "ui/cook/node_status.h"
#include "ui/document/graph_document.h"

namespace tfd::ui {

class CookController : public QObject {
  Q_OBJECT

 public:
  explicit CookController(GraphDocument& document, QObject* parent = nullptr);
  /// Cancels a running cook and joins its thread (at exit; the cancel makes it quick).
  ~CookController() override;

  void setAutoCook(bool on);
  bool autoCook() const { return autoCook_; }
  /// Cooks the current document soon (coalesces several requests; waits for a running cook
  /// to stop if one was cancelled).
  void requestCook();
  /// Cooks everything, exporters included (writes their files).
  void writeOutputs();
  /// Asks the running cook to stop; returns at once.
  void cancel();
  bool isCooking() const { return worker_.joinable(); }

  /// The last finished cook (complete or cancelled) and the graph it cooked.
  const graph::CookResult& lastResult() const { return result_; }
  const graph::Graph& lastGraph() const { return *lastGraph_; }
  const NodeStatusMap& statuses() const { return statuses_; }
  /// Fraction of the running cook done, in [0, 1].
  double progress() const { return progress_; }
  /// Cooks finished so far (complete or cancelled).
  int finishedCooks() const { return finished_; }

 signals:
  void cookStarted();
  void progressChanged(double fraction, const QString& stage);
  void statusChanged(const QString& node, const tfd::ui::NodeStatus& status);
  void cookFinished(bool cancelled);

 private:
  class Observer;
  struct Live;
  void start(bool withSinks);
  void finish(graph::CookResult result, std::shared_ptr<graph::Graph> cooked);
  void publishProgress();

  GraphDocument& document_;
  std::unique_ptr<graph::Evaluator> evaluator_;
  std::unique_ptr<Observer> observer_;
  std::shared_ptr<Live> live_;
  std::thread worker_;
  std::atomic<bool> cancel_{false};
  bool autoCook_ = true;
  bool pending_ = false, pendingWithSinks_ = false, scheduled_ = false;
  graph::CookResult result_;
  std::shared_ptr<graph::Graph> lastGraph_;
  NodeStatusMap statuses_;
  double progress_ = 0;
  int finished_ = 0;
};

}  // namespace tfd::ui
