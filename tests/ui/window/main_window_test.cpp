// The main window offscreen (no OpenGL drawn): files (New, Open, Save, Save As, recent files,
// the dirty marker in the title), autosave and the offer to recover it after a crash, the
// selection feeding the panels, and the cancel button stopping a running cook.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QSettings>
#include <QStandardPaths>
#include <QToolButton>

#include <fstream>

#include <thread>

#include "graph/graph_file.h"
#include "nodes/register_all.h"
#include "tests/support/graph_test_nodes.h"
#include "tests/support/temp_dir.h"
#include "ui/canvas/canvas_scene.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/params/param_panel.h"
#include "ui/viewport/viewport_panel.h"
#include "ui/window/document_files.h"
#include "ui/window/main_window.h"

namespace tfd::ui {
namespace {

bool spinUntil(const std::function<bool()>& done, int timeoutMs = 20000) {
  QElapsedTimer t;
  t.start();
  while (!done() && t.elapsed() < timeoutMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done();
}

class Window : public ::testing::Test {
 protected:
  void SetUp() override {
    // Settings and the untitled autosave go to the temporary folder, not the user's.
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope,
                       QString::fromStdString((dir.path() / "settings").string()));
    QCoreApplication::setOrganizationName("tfd-test");
    QCoreApplication::setApplicationName("main-window-test");
    QSettings().clear();
    nodes::registerAll(registry);
    test::registerTestNodes(registry);
  }
  std::unique_ptr<MainWindow> makeWindow() {
    auto w = std::make_unique<MainWindow>(registry);
    w->prompts.saveChanges = [this](const QString& text) {
      asked << text;
      return answer;
    };
    w->prompts.recover = [this](const QString& text) {
      asked << text;
      return recoverAnswer;
    };
    w->prompts.path = [this](bool, const QString&) { return nextPath; };
    w->prompts.error = [this](const QString& text) { errors << text; };
    w->cook().setAutoCook(false);
    return w;
  }
  std::filesystem::path writeGraph(const std::string& name) {
    graph::Graph g(registry);
    g.addNode("Constant", "c");
    g.addNode("Scale", "s");
    g.connect({"c", "out"}, {"s", "in"});
    const auto path = dir.path() / name;
    graph::saveGraphFile(g, path);
    return path;
  }

  test::TempDir dir{"main-window"};
  graph::NodeRegistry registry;
  QStringList asked, errors;
  Prompts::Answer answer = Prompts::Answer::Cancel;
  bool recoverAnswer = true;
  QString nextPath;
};

TEST_F(Window, TheTitleNamesTheFileAndMarksUnsavedChanges) {
  auto w = makeWindow();
  EXPECT_EQ(w->windowTitle(), "untitled[*] — tfd editor");
  EXPECT_FALSE(w->isWindowModified());
  w->document().addNode("Constant", {}, "c");
  EXPECT_TRUE(w->isWindowModified());
  nextPath = QString::fromStdString((dir.path() / "first.tfd.json").string());
  ASSERT_TRUE(w->save()) << "Save of an untitled graph asks for a path";
  EXPECT_EQ(w->windowTitle(), "first.tfd.json[*] — tfd editor");
  EXPECT_FALSE(w->isWindowModified());
  w->document().undoStack()->undo();
  EXPECT_TRUE(w->isWindowModified());
  w->document().undoStack()->redo();
  EXPECT_FALSE(w->isWindowModified()) << "back at the saved state";
}

TEST_F(Window, UnsavedChangesAreAskedAboutAndCancelKeepsThem) {
  auto w = makeWindow();
  const auto path = writeGraph("g.tfd.json");
  w->document().addNode("Constant", {}, "mine");
  answer = Prompts::Answer::Cancel;
  EXPECT_FALSE(w->openFile(path));
  EXPECT_EQ(asked.size(), 1);
  EXPECT_TRUE(w->document().graph().findNode("mine"));
  answer = Prompts::Answer::Discard;
  EXPECT_TRUE(w->openFile(path));
  EXPECT_EQ(w->document().graph().nodeCount(), 2u);
  EXPECT_EQ(w->document().filePath(), path);
  EXPECT_TRUE(w->newFile());
  EXPECT_EQ(w->document().graph().nodeCount(), 0u) << "a clean document needs no question";
  EXPECT_EQ(asked.size(), 2);
}

TEST_F(Window, OpenAndSaveAsKeepRecentFilesNewestFirst) {
  auto w = makeWindow();
  const auto a = writeGraph("a.tfd.json");
  const auto b = writeGraph("b.tfd.json");
  ASSERT_TRUE(w->openFile(a));
  ASSERT_TRUE(w->openFile(b));
  nextPath = QString::fromStdString((dir.path() / "c.tfd.json").string());
  ASSERT_TRUE(w->saveAs());
  EXPECT_EQ(w->document().filePath(), dir.path() / "c.tfd.json");
  EXPECT_EQ(graph::readTextFile(dir.path() / "c.tfd.json"), graph::readTextFile(b));
  ASSERT_TRUE(w->openFile(a));
  const QStringList recent = w->files().recentFiles();
  ASSERT_EQ(recent.size(), 3);
  EXPECT_TRUE(recent[0].endsWith("a.tfd.json"));
  EXPECT_TRUE(recent[1].endsWith("c.tfd.json"));
  EXPECT_TRUE(recent[2].endsWith("b.tfd.json"));
  // A file that does not load is an error naming it, and the document stays as it was.
  std::ofstream(dir.path() / "bad.tfd.json") << "{\"format\": 7}";
  EXPECT_FALSE(w->openFile(dir.path() / "bad.tfd.json"));
  ASSERT_EQ(errors.size(), 1);
  EXPECT_TRUE(errors[0].contains("bad.tfd.json")) << errors[0].toStdString();
  EXPECT_EQ(w->document().filePath(), a);
}

TEST_F(Window, AnAutosaveLeftByACrashIsOfferedAndRecovered) {
  const auto path = writeGraph("work.tfd.json");
  const std::string saved = graph::readTextFile(path);
  std::string edited;
  {
    auto w = makeWindow();
    ASSERT_TRUE(w->openFile(path));
    EXPECT_FALSE(w->files().autosaveNow()) << "nothing to autosave in a clean document";
    w->document().setParam("s", "factor", 7.0);
    ASSERT_TRUE(w->files().autosaveNow());
    EXPECT_FALSE(w->files().autosaveNow()) << "no change since the last autosave";
    edited = w->document().text();
    EXPECT_EQ(graph::readTextFile(DocumentFiles::autosavePath(path)), edited);
    EXPECT_EQ(graph::readTextFile(path), saved) << "autosave never touches the file";
    // The window goes away without closing: a crash, as far as the files are concerned.
  }
  ASSERT_TRUE(std::filesystem::exists(DocumentFiles::autosavePath(path)));
  auto w = makeWindow();
  recoverAnswer = true;
  ASSERT_TRUE(w->openFile(path));
  ASSERT_EQ(asked.size(), 1);
  EXPECT_TRUE(asked[0].contains("work.tfd.json")) << asked[0].toStdString();
  EXPECT_EQ(w->document().text(), edited);
  EXPECT_TRUE(w->isWindowModified()) << "recovered changes are not saved yet";
  EXPECT_EQ(w->document().filePath(), path);
  ASSERT_TRUE(w->save());
  EXPECT_EQ(graph::readTextFile(path), edited);
  EXPECT_FALSE(std::filesystem::exists(DocumentFiles::autosavePath(path)))
      << "a save removes the autosave";
  // Declining removes the side file; an identical one is not offered at all.
  auto w2 = makeWindow();
  ASSERT_TRUE(w2->openFile(path));
  w2->document().setParam("s", "factor", 9.0);
  EXPECT_TRUE(w2->files().autosaveNow());
  w2.reset();
  auto w3 = makeWindow();
  recoverAnswer = false;
  ASSERT_TRUE(w3->openFile(path));
  EXPECT_FALSE(std::filesystem::exists(DocumentFiles::autosavePath(path)));
  EXPECT_EQ(w3->document().text(), edited);
}

TEST_F(Window, AnUntitledGraphIsRecoveredAtStartUp) {
  {
    auto w = makeWindow();
    w->document().addNode("Constant", {}, "lonely");
    ASSERT_TRUE(w->files().autosaveNow());
    EXPECT_TRUE(std::filesystem::exists(DocumentFiles::autosavePath({})));
  }
  auto w = makeWindow();
  w->offerUntitledRecovery();
  EXPECT_TRUE(w->document().graph().findNode("lonely"));
  EXPECT_TRUE(w->document().filePath().empty());
  EXPECT_TRUE(w->isWindowModified());
  answer = Prompts::Answer::Discard;
  EXPECT_TRUE(w->close());
  EXPECT_FALSE(std::filesystem::exists(DocumentFiles::autosavePath({})))
      << "a clean close leaves no autosave behind";
}

TEST_F(Window, SelectingANodeFillsTheParameterPanelAndTheViewportTarget) {
  auto w = makeWindow();
  w->document().addNode("LocalSmooth", {}, "smooth");
  w->document().addNode("Constant", {}, "c");
  w->canvas()->selectNodes({"smooth"});
  EXPECT_EQ(w->params()->node(), "smooth");
  EXPECT_EQ(w->viewport()->selectedNode(), "smooth");
  EXPECT_NE(w->params()->editor("pick"), nullptr);
  w->canvas()->selectNodes({"smooth", "c"});
  EXPECT_EQ(w->params()->node(), "");
}

TEST_F(Window, TheCancelButtonStopsARunningCook) {
  auto w = makeWindow();
  w->document().addNode("Wait", {}, "slow");
  w->document().setParam("slow", "seconds", 30.0);
  w->cook().setAutoCook(true);
  ASSERT_TRUE(spinUntil([&] { return w->cook().isCooking(); }));
  EXPECT_TRUE(w->progressBar()->isVisibleTo(w.get()));
  QElapsedTimer t;
  t.start();
  ASSERT_TRUE(w->cancelButton()->isEnabled());
  w->cancelButton()->click();
  ASSERT_TRUE(spinUntil([&] { return !w->cook().isCooking() && w->cook().finishedCooks() == 1; }));
  EXPECT_FALSE(w->cancelButton()->isEnabled());
  EXPECT_LT(t.elapsed(), 5000);
  EXPECT_TRUE(w->cook().lastResult().cancelled);
  EXPECT_FALSE(w->progressBar()->isVisibleTo(w.get()));
}

}  // namespace
}  // namespace tfd::ui
