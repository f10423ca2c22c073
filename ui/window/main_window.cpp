#include "ui/window/main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QSplitter>
#include <QStatusBar>
#include <QToolButton>

#include "ui/canvas/canvas_scene.h"
#include "ui/canvas/canvas_view.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/params/param_panel.h"
#include "ui/viewport/viewport_panel.h"
#include "ui/window/document_files.h"
#include "ui/window/info_panel.h"

namespace tfd::ui {

namespace {

Prompts defaultPrompts(QWidget* parent) {
  Prompts p;
  p.saveChanges = [parent](const QString& text) {
    const auto b = QMessageBox::question(
        parent, "Unsaved changes", text,
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    return b == QMessageBox::Save      ? Prompts::Answer::Save
           : b == QMessageBox::Discard ? Prompts::Answer::Discard
                                       : Prompts::Answer::Cancel;
  };
  p.recover = [parent](const QString& text) {
    return QMessageBox::question(parent, "Recover unsaved changes?", text,
                                 QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::Yes) == QMessageBox::Yes;
  };
  p.path = [parent](bool save, const QString& suggestion) {
    const QString filter = "tfd graphs (*.tfd.json);;JSON files (*.json);;All files (*)";
    QString path = save ? QFileDialog::getSaveFileName(parent, "Save graph", suggestion, filter)
                        : QFileDialog::getOpenFileName(parent, "Open graph", suggestion, filter);
    if (save && !path.isEmpty() && !path.endsWith(".json")) path += ".tfd.json";
    return path;
  };
  p.error = [parent](const QString& text) { QMessageBox::warning(parent, "tfd editor", text); };
  return p;
}

}  // namespace

MainWindow::MainWindow(const graph::NodeRegistry& registry, QWidget* parent)
    : QMainWindow(parent), prompts(defaultPrompts(this)) {
  document_ = std::make_unique<GraphDocument>(registry);
  cook_ = new CookController(*document_, this);
  files_ = new DocumentFiles(*document_, this);
  buildLayout();
  buildStatusBar();
  buildMenus();
  wireSignals();
  updateTitle();
  resize(1280, 800);
}

MainWindow::~MainWindow() {
  // Stop the cook first, then the views (they refer to the document), then the document.
  disconnect(scene_, nullptr, this, nullptr);
  delete cook_;
  cook_ = nullptr;
  delete takeCentralWidget();
  qDeleteAll(findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly));
  delete scene_;
  delete files_;
}

void MainWindow::buildLayout() {
  scene_ = new CanvasScene(*document_, this);
  canvasView_ = new CanvasView(scene_);
  viewport_ = new ViewportPanel(*document_, *cook_);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(canvasView_);
  split->addWidget(viewport_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  split->setSizes({560, 460});
  setCentralWidget(split);

  params_ = new ParamPanel(*document_);
  auto* paramDock = new QDockWidget("Parameters", this);
  paramDock->setObjectName("parameters");
  paramDock->setWidget(params_);
  addDockWidget(Qt::RightDockWidgetArea, paramDock);
  info_ = new InfoPanel(*cook_);
  auto* infoDock = new QDockWidget("Info", this);
  infoDock->setObjectName("info");
  infoDock->setWidget(info_);
  addDockWidget(Qt::RightDockWidgetArea, infoDock);
  resizeDocks({paramDock}, {320}, Qt::Horizontal);
  resizeDocks({paramDock, infoDock}, {520, 200}, Qt::Vertical);
}

void MainWindow::buildStatusBar() {
  stage_ = new QLabel(this);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setMaximumWidth(220);
  progress_->setTextVisible(false);
  progress_->setVisible(false);
  cancel_ = new QToolButton(this);
  cancel_->setText("Cancel");
  cancel_->setToolTip("Stop the running cook (Esc)");
  cancel_->setEnabled(false);
  connect(cancel_, &QToolButton::clicked, cook_, &CookController::cancel);
  statusBar()->addPermanentWidget(stage_);
  statusBar()->addPermanentWidget(progress_);
  statusBar()->addPermanentWidget(cancel_);
}

void MainWindow::wireSignals() {
  connect(scene_, &CanvasScene::selectedNodesChanged, this, [this] {
    const std::vector<std::string> selected = scene_->selectedNodeNames();
    const std::string one = selected.size() == 1 ? selected.front() : std::string();
    params_->setNode(one);
    info_->setNode(one);
    viewport_->setSelectedNode(one);
  });
  connect(cook_, &CookController::statusChanged, this,
          [this](const QString& node, const NodeStatus& s) {
            scene_->setStatus(node.toStdString(), s);
          });
  connect(cook_, &CookController::cookStarted, this, [this] {
    progress_->setValue(0);
    progress_->setVisible(true);
    cancel_->setEnabled(true);
  });
  connect(cook_, &CookController::progressChanged, this,
          [this](double fraction, const QString& stage) {
            progress_->setValue(int(fraction * 1000));
            stage_->setText(stage);
          });
  connect(cook_, &CookController::cookFinished, this, [this](bool cancelled) {
    scene_->setStatuses(cook_->statuses());
    progress_->setVisible(false);
    cancel_->setEnabled(false);
    stage_->setText(cancelled ? "Cook cancelled" : QString());
  });
  connect(document_.get(), &GraphDocument::fileStateChanged, this, &MainWindow::updateTitle);
  connect(document_.get(), &GraphDocument::editRefused, this,
          [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(viewport_, &ViewportPanel::message, this,
          [this](const QString& m) { statusBar()->showMessage(m, 6000); });
  connect(files_, &DocumentFiles::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
}

QString MainWindow::titleText() const {
  const std::filesystem::path& p = document_->filePath();
  const QString name = p.empty() ? "untitled" : QString::fromStdString(p.filename().string());
  return name + "[*] — tfd editor";
}

void MainWindow::updateTitle() {
  setWindowTitle(titleText());
  setWindowModified(document_->isDirty());
}

void MainWindow::showError(const QString& text) {
  statusBar()->showMessage(text, 10000);
  if (prompts.error) prompts.error(text);
}

bool MainWindow::maybeSave() {
  if (!document_->isDirty()) return true;
  const QString name = document_->filePath().empty()
                           ? QString("the untitled graph")
                           : QString::fromStdString(document_->filePath().filename().string());
  switch (prompts.saveChanges("Save the changes to " + name + "?")) {
    case Prompts::Answer::Save:
      return save();
    case Prompts::Answer::Discard:
      files_->discardAutosave();
      return true;
    case Prompts::Answer::Cancel:
      return false;
  }
  return false;
}

bool MainWindow::newFile() {
  if (!maybeSave()) return false;
  document_->newDocument();
  return true;
}

bool MainWindow::openFile(const std::filesystem::path& path) {
  if (!maybeSave()) return false;
  try {
    files_->open(path);
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
  if (auto side = files_->recoverable(path)) {
    if (prompts.recover(QString::fromStdString(
            "The editor did not close cleanly: " + side->filename().string() +
            " holds changes to " + path.filename().string() +
            " that were never saved. "
            "Recover them?"))) {
      try {
        files_->recover(*side, path);
      } catch (const std::exception& e) {
        showError(QString::fromStdString(e.what()));
      }
    } else {
      std::error_code ec;
      std::filesystem::remove(*side, ec);
    }
  }
  canvasView_->frameAll();
  return true;
}

void MainWindow::offerUntitledRecovery() {
  auto side = files_->recoverable({});
  if (!side) return;
  if (prompts.recover("The editor did not close cleanly and an untitled graph was never saved. "
                      "Recover it?")) {
    try {
      files_->recover(*side, {});
      canvasView_->frameAll();
      return;
    } catch (const std::exception& e) {
      showError(QString::fromStdString(e.what()));
    }
  }
  std::error_code ec;
  std::filesystem::remove(*side, ec);
}

bool MainWindow::open() {
  const QString dir = document_->filePath().empty()
                          ? QString()
                          : QString::fromStdString(document_->filePath().parent_path().string());
  const QString path = prompts.path(false, dir);
  return !path.isEmpty() && openFile(path.toStdString());
}

bool MainWindow::saveTo(const std::filesystem::path& path) {
  try {
    files_->save(path);
  } catch (const std::exception& e) {
    showError(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage("Saved " + QString::fromStdString(path.string()), 4000);
  return true;
}

bool MainWindow::save() {
  return document_->filePath().empty() ? saveAs() : saveTo(document_->filePath());
}

bool MainWindow::saveAs() {
  const QString suggestion = document_->filePath().empty()
                                 ? QString("untitled.tfd.json")
                                 : QString::fromStdString(document_->filePath().string());
  const QString path = prompts.path(true, suggestion);
  return !path.isEmpty() && saveTo(path.toStdString());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  files_->discardAutosave();
  event->accept();
}

}  // namespace tfd::ui
