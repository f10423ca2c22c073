// The main window's menus and shortcuts (main_window.h).
#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QUndoStack>

#include "ui/canvas/canvas_scene.h"
#include "ui/canvas/canvas_view.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/viewport/viewport_panel.h"
#include "ui/window/document_files.h"
#include "ui/window/main_window.h"

namespace tfd::ui {

namespace {

QAction* menuAction(QMenu* menu, const QString& text, const QKeySequence& key,
                    const std::function<void()>& run) {
  QAction* a = menu->addAction(text);
  if (!key.isEmpty()) a->setShortcut(key);
  QObject::connect(a, &QAction::triggered, menu, [run] { run(); });
  return a;
}

const char* kShortcutsHelp =
    "<b>Canvas</b>: Tab node menu · drag from a port to link (compatible ports light up; drop "
    "on empty space to add a matching node) · Delete · F frame selection · A frame all · wheel "
    "zoom · middle or Alt + drag pan · drag on empty space to box select.<br>"
    "<b>Viewport</b>: left drag orbit · middle or Shift + drag pan · right drag or wheel zoom · "
    "F frame · 0 iso, 1 x, 2 y, 3 z · click a degenerate curve to fill the selected node's "
    "<i>picks</i> or <i>pick</i> · click in space to add a control point to a selected "
    "curve's <i>points</i>.<br>"
    "<b>Nodes</b>: click the strip at a node's left edge to show it in the viewport.";

}  // namespace

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  menuAction(file, "&New", QKeySequence::New, [this] { newFile(); });
  menuAction(file, "&Open…", QKeySequence::Open, [this] { open(); });
  recentMenu_ = file->addMenu("Open &Recent");
  rebuildRecentMenu();
  file->addSeparator();
  menuAction(file, "&Save", QKeySequence::Save, [this] { save(); });
  menuAction(file, "Save &As…", QKeySequence::SaveAs, [this] { saveAs(); });
  file->addSeparator();
  menuAction(file, "&Quit", QKeySequence::Quit, [this] { close(); });

  buildEditMenu(menuBar()->addMenu("&Edit"));

  QMenu* view = menuBar()->addMenu("&View");
  menuAction(view, "Frame All Nodes", QKeySequence("Ctrl+Shift+A"),
             [this] { canvasView_->frameAll(); });
  menuAction(view, "Frame Viewport", QKeySequence("Ctrl+Shift+F"),
             [this] { viewport_->view()->frameAll(); });
  menuAction(view, "Display Selected Node", QKeySequence("Ctrl+T"), [this] {
    const auto selected = scene_->selectedNodeNames();
    if (selected.size() == 1) document_->setDisplayNode(selected.front());
  });
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());

  buildCookMenu(menuBar()->addMenu("&Cook"));

  QMenu* help = menuBar()->addMenu("&Help");
  menuAction(help, "&Shortcuts", QKeySequence::HelpContents,
             [this] { QMessageBox::information(this, "Shortcuts", kShortcutsHelp); });
}

void MainWindow::buildEditMenu(QMenu* edit) {
  QAction* undo = document_->undoStack()->createUndoAction(this, "&Undo");
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = document_->undoStack()->createRedoAction(this, "&Redo");
  redo->setShortcuts({QKeySequence::Redo, QKeySequence("Ctrl+Y")});
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  // Canvas editing: only while the canvas has focus, so text fields keep their own keys.
  auto canvasAction = [this, edit](const QString& text, const QKeySequence& key,
                                   const std::function<void()>& run) {
    QAction* a = menuAction(edit, text, key, run);
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    canvasView_->addAction(a);
    return a;
  };
  canvasAction("Cu&t", QKeySequence::Cut, [this] {
    const auto names = scene_->selectedNodeNames();
    if (names.empty()) return;
    QApplication::clipboard()->setText(QString::fromStdString(document_->copyText(names)));
    scene_->deleteSelection();
  });
  canvasAction("&Copy", QKeySequence::Copy, [this] {
    const auto names = scene_->selectedNodeNames();
    if (!names.empty())
      QApplication::clipboard()->setText(QString::fromStdString(document_->copyText(names)));
  });
  canvasAction("&Paste", QKeySequence::Paste, [this] {
    const auto added =
        document_->paste(QApplication::clipboard()->text().toStdString(), QPointF(40, 40));
    if (!added.empty()) scene_->selectNodes(added);
  });
  canvasAction("&Duplicate", QKeySequence("Ctrl+D"), [this] {
    const auto added = document_->duplicate(scene_->selectedNodeNames());
    if (!added.empty()) scene_->selectNodes(added);
  });
  canvasAction("&Delete", QKeySequence::Delete, [this] { scene_->deleteSelection(); });
  canvasAction("Select &All", QKeySequence::SelectAll, [this] {
    std::vector<std::string> all;
    for (const graph::Node& n : document_->graph().nodes()) all.push_back(n.name());
    scene_->selectNodes(all);
  });
}

void MainWindow::buildCookMenu(QMenu* cook) {
  QAction* autoCook = cook->addAction("&Auto Cook");
  autoCook->setCheckable(true);
  autoCook->setChecked(cook_->autoCook());
  connect(autoCook, &QAction::toggled, cook_, &CookController::setAutoCook);
  menuAction(cook, "Cook &Now", QKeySequence("F5"), [this] { cook_->requestCook(); });
  menuAction(cook, "&Write Outputs", QKeySequence("Ctrl+Shift+W"),
             [this] { cook_->writeOutputs(); });
  menuAction(cook, "&Cancel", QKeySequence("Esc"), [this] { cook_->cancel(); });
}

void MainWindow::rebuildRecentMenu() {
  if (!recentMenu_) return;
  recentMenu_->clear();
  const QStringList recent = files_->recentFiles();
  for (const QString& path : recent) {
    QAction* a = recentMenu_->addAction(QFileInfo(path).fileName());
    a->setToolTip(path);
    a->setStatusTip(path);
    connect(a, &QAction::triggered, this, [this, path] { openFile(path.toStdString()); });
  }
  recentMenu_->setEnabled(!recent.isEmpty());
  if (!recent.isEmpty()) {
    recentMenu_->addSeparator();
    QAction* clear = recentMenu_->addAction("Clear List");
    connect(clear, &QAction::triggered, this, [this] {
      QSettings().remove("recentFiles");
      rebuildRecentMenu();
    });
  }
}

}  // namespace tfd::ui
