#pragma once
// The editor's main window: the node canvas in the middle, the viewport beside it, the
// parameter panel and the info panel docked at the right, a progress bar with a cancel button
// in the status bar; menus and shortcuts for files (New, Open, Open Recent, Save, Save As),
// editing (undo/redo, cut/copy/paste as graph-file text, duplicate, delete) and cooking. The
// title shows the file name with a dirty marker. Everything the window shows about nodes
// comes from the registry's declarations, so new node types need no change here.
//
// Scripts and tests drive it through the same public API the menus use; the questions it asks
// (save changes? recover an autosave? which file?) go through `prompts`, which tests replace.
#include <QMainWindow>

#include <filesystem>
#include <functional>
#include <memory>

#include "graph/node_registry.h"

class QAction;
class QLabel;
class QMenu;
class QProgressBar;
class QToolButton;

namespace tfd::ui {

class CanvasScene;
class CanvasView;
class CookController;
class DocumentFiles;
class GraphDocument;
class InfoPanel;
class ParamPanel;
class ViewportPanel;

/// The questions the window asks the user (QMessageBox / QFileDialog by default).
struct Prompts {
  enum class Answer { Save, Discard, Cancel };
  /// Unsaved changes before they would be lost.
  std::function<Answer(const QString& text)> saveChanges;
  /// An autosave is newer than the file: true to recover it.
  std::function<bool(const QString& text)> recover;
  /// A path to open (save = false) or save to; empty to cancel.
  std::function<QString(bool save, const QString& suggestion)> path;
  /// An error to show.
  std::function<void(const QString& text)> error;
};

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(const graph::NodeRegistry& registry, QWidget* parent = nullptr);
  ~MainWindow() override;

  GraphDocument& document() { return *document_; }
  CookController& cook() { return *cook_; }
  DocumentFiles& files() { return *files_; }
  CanvasScene* canvas() const { return scene_; }
  CanvasView* canvasView() const { return canvasView_; }
  ParamPanel* params() const { return params_; }
  InfoPanel* info() const { return info_; }
  ViewportPanel* viewport() const { return viewport_; }
  QProgressBar* progressBar() const { return progress_; }
  QToolButton* cancelButton() const { return cancel_; }
  Prompts prompts;

  // ---- file commands (what the menus call); false when cancelled or failed
  bool newFile();
  /// Opens a file (asks about unsaved changes first, offers to recover its autosave).
  bool openFile(const std::filesystem::path& path);
  bool open();  ///< asks for the path
  bool save();  ///< Save As when the document has no file yet
  bool saveAs();
  bool saveTo(const std::filesystem::path& path);
  /// At start-up: offers to recover the untitled document's autosave, if there is one.
  void offerUntitledRecovery();

  /// "name.tfd.json[*] — tfd editor" (Qt shows * when modified).
  QString titleText() const;

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildLayout();
  void buildMenus();
  void buildEditMenu(QMenu* menu);
  void buildCookMenu(QMenu* menu);
  void buildStatusBar();
  void wireSignals();
  void rebuildRecentMenu();
  void updateTitle();
  /// Asks about unsaved changes; false when the user cancels (or saving fails).
  bool maybeSave();
  void showError(const QString& text);

  std::unique_ptr<GraphDocument> document_;
  CookController* cook_ = nullptr;
  DocumentFiles* files_ = nullptr;
  CanvasScene* scene_ = nullptr;
  CanvasView* canvasView_ = nullptr;
  ParamPanel* params_ = nullptr;
  InfoPanel* info_ = nullptr;
  ViewportPanel* viewport_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QToolButton* cancel_ = nullptr;
  QLabel* stage_ = nullptr;
  QMenu* recentMenu_ = nullptr;
};

}  // namespace tfd::ui
