// Background cooking (offscreen): re-cooks only downstream of an edit, an edit cancels the
// running cook first, the UI thread keeps running while a node cooks, exporters only on demand.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <chrono>
#include <thread>

#include "tests/support/graph_test_nodes.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"

namespace tfd::ui {
namespace {

/// Runs the event loop until `done` or the timeout; returns done().
bool spinUntil(const std::function<bool()>& done, int timeoutMs = 10000) {
  QElapsedTimer t;
  t.start();
  while (!done() && t.elapsed() < timeoutMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done();
}

class Cooking : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    test::cookLog().clear();
    doc = std::make_unique<GraphDocument>(registry);
    cook = std::make_unique<CookController>(*doc);
  }
  void TearDown() override {
    cook.reset();
    doc.reset();
  }
  /// Waits until `n` cooks have finished.
  void waitForCooks(int n) {
    ASSERT_TRUE(spinUntil([&] { return cook->finishedCooks() >= n && !cook->isCooking(); }))
        << "cooks finished: " << cook->finishedCooks();
  }
  graph::NodeState stateOf(const std::string& node) {
    const graph::NodeReport* r = cook->lastResult().report(node);
    return r ? r->state : graph::NodeState::NotRequested;
  }
  graph::NodeRegistry registry;
  std::unique_ptr<GraphDocument> doc;
  std::unique_ptr<CookController> cook;
};

TEST_F(Cooking, AnEditReCooksOnlyWhatIsDownstream) {
  cook->setAutoCook(false);
  doc->addNode("Constant", {}, "c");
  doc->addNode("Scale", {}, "s");
  doc->addNode("Constant", {}, "other");
  doc->connect({"c", "out"}, {"s", "in"});
  cook->setAutoCook(true);
  waitForCooks(1);
  EXPECT_EQ(stateOf("c"), graph::NodeState::Cooked);
  EXPECT_EQ(stateOf("s"), graph::NodeState::Cooked);
  EXPECT_EQ(cook->statuses().at("s").state, NodeStatus::State::Cooked);
  doc->setParam("s", "factor", 5.0);
  waitForCooks(2);
  EXPECT_EQ(stateOf("c"), graph::NodeState::Cached);
  EXPECT_EQ(stateOf("other"), graph::NodeState::Cached);
  EXPECT_EQ(stateOf("s"), graph::NodeState::Cooked);
  EXPECT_EQ(cook->lastResult().output<test::Number>("s", "out")->value, 5.0);
  // Undo: the earlier result is still cached, nothing cooks.
  doc->undoStack()->undo();
  waitForCooks(3);
  EXPECT_EQ(stateOf("s"), graph::NodeState::Cached);
}

TEST_F(Cooking, AnEditCancelsTheRunningCookBeforeTheDocumentChanges) {
  doc->addNode("Wait", {}, "slow");
  doc->setParam("slow", "seconds", 20.0);
  ASSERT_TRUE(spinUntil([&] {
    auto it = cook->statuses().find("slow");
    return it != cook->statuses().end() && it->second.state == NodeStatus::State::Cooking;
  }));
  bool cancelledFirst = false;
  QObject::connect(doc.get(), &GraphDocument::aboutToChange, [&](int) {
    // Runs after the controller's own handler (connected first): the flag is already set.
    cancelledFirst = cook->isCooking();
  });
  QElapsedTimer t;
  t.start();
  const int before = cook->finishedCooks();
  doc->setParam("slow", "seconds", 0.01);
  EXPECT_TRUE(cancelledFirst);
  EXPECT_LT(t.elapsed(), 100) << "the edit itself does not wait for the cook";
  waitForCooks(before + 2);  // the cancelled cook, then the new one
  EXPECT_LT(t.elapsed(), 3000);
  EXPECT_EQ(stateOf("slow"), graph::NodeState::Cooked);
  EXPECT_FALSE(cook->lastResult().cancelled);
}

TEST_F(Cooking, TheEventLoopKeepsRunningWhileANodeCooks) {
  int ticks = 0;
  QTimer timer;
  QObject::connect(&timer, &QTimer::timeout, [&] { ++ticks; });
  timer.start(10);
  std::vector<double> progress;
  QObject::connect(cook.get(), &CookController::progressChanged,
                   [&](double f, const QString&) { progress.push_back(f); });
  doc->addNode("Wait", {}, "slow");
  doc->setParam("slow", "seconds", 0.6);
  waitForCooks(1);  // both edits were made before the event loop ran: one cook
  ASSERT_NE(cook->lastResult().report("slow"), nullptr);
  EXPECT_GE(cook->lastResult().report("slow")->seconds, 0.5);
  EXPECT_GT(ticks, 20) << "the UI thread was blocked";
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
}

TEST_F(Cooking, CancelStopsACookAtOnce) {
  doc->addNode("Wait", {}, "slow");
  doc->setParam("slow", "seconds", 30.0);
  ASSERT_TRUE(spinUntil([&] { return cook->isCooking(); }));
  const int before = cook->finishedCooks();
  QElapsedTimer t;
  t.start();
  cook->cancel();
  waitForCooks(before + 1);
  EXPECT_LT(t.elapsed(), 2000);
  EXPECT_TRUE(cook->lastResult().cancelled);
  EXPECT_EQ(stateOf("slow"), graph::NodeState::Cancelled);
}

TEST_F(Cooking, ExportersRunOnlyWhenOutputsAreWritten) {
  doc->addNode("Constant", {}, "c");
  doc->addNode("Sink", {}, "sink");
  doc->connect({"c", "out"}, {"sink", "in"});
  waitForCooks(1);
  EXPECT_EQ(test::cookLog().count("sink"), 0);
  EXPECT_EQ(stateOf("sink"), graph::NodeState::NotRequested);
  const int before = cook->finishedCooks();
  cook->writeOutputs();
  waitForCooks(before + 1);
  EXPECT_EQ(test::cookLog().count("sink"), 1);
  EXPECT_EQ(stateOf("sink"), graph::NodeState::Cooked);
}

TEST_F(Cooking, FailuresAndDownstreamAreReportedPerNode) {
  doc->addNode("Constant", {}, "c");
  doc->addNode("Scale", {}, "s");
  doc->addNode("Scale", {}, "after");
  doc->connect({"c", "out"}, {"s", "in"});
  doc->connect({"s", "out"}, {"after", "in"});
  doc->setParam("s", "fail", true);
  waitForCooks(1);
  ASSERT_TRUE(spinUntil([&] { return cook->statuses().count("after") > 0; }));
  EXPECT_EQ(cook->statuses().at("s").state, NodeStatus::State::Failed);
  EXPECT_FALSE(cook->statuses().at("s").headline().empty());
  EXPECT_EQ(cook->statuses().at("after").state, NodeStatus::State::UpstreamFailed);
  EXPECT_EQ(cook->statuses().at("after").failedNode, "s");
  EXPECT_EQ(cook->statuses().at("c").state, NodeStatus::State::Cooked);
}

}  // namespace
}  // namespace tfd::ui
