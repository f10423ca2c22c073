#pragma once
// The editor's file keeping around a GraphDocument: open and save with the recent-files list
// (QSettings), and autosave. While the document has unsaved changes, its text is written every
// interval to a side file next to it (".<name>.autosave", or "untitled.tfd.json.autosave" in
// the application's data folder for a document never saved); a save or a clean close removes
// that file. A side file still there when a document is opened means the editor did not close
// cleanly: when it differs from the file, the editor offers to recover it (recoverable()).
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <filesystem>
#include <optional>

#include "ui/document/graph_document.h"

namespace tfd::ui {

class DocumentFiles : public QObject {
  Q_OBJECT

 public:
  explicit DocumentFiles(GraphDocument& document, QObject* parent = nullptr);

  /// The autosave side file of a document file ("" path: the untitled document's).
  static std::filesystem::path autosavePath(const std::filesystem::path& file);

  /// Opens a file (throws graph::GraphError) and records it in the recent files.
  void open(const std::filesystem::path& path);
  /// Saves (throws graph::GraphError), removes the autosave, records it in the recent files.
  void save(const std::filesystem::path& path);
  /// Forgets the current autosave (a clean close or New after the user chose to discard).
  void discardAutosave();

  /// An autosave left for `file` by a session that did not close cleanly, whose text differs
  /// from the file's (nothing otherwise; a stale identical one is removed).
  std::optional<std::filesystem::path> recoverable(const std::filesystem::path& file) const;
  /// Replaces the document by the autosave's graph, as unsaved changes to `file`.
  void recover(const std::filesystem::path& autosave, const std::filesystem::path& file);

  void setAutosaveInterval(int milliseconds);
  /// Writes the autosave now when the document has changes not yet autosaved; true if written.
  bool autosaveNow();

  QStringList recentFiles() const;
  void addRecent(const std::filesystem::path& path);
  static constexpr int kMaxRecent = 10;

 signals:
  void recentFilesChanged();

 private:
  GraphDocument& document_;
  QTimer timer_;
  std::uint64_t autosavedRevision_ = 0;
  std::filesystem::path autosaved_;  ///< the side file written last ("" none)
};

}  // namespace tfd::ui
