#include "ui/window/document_files.h"

#include <QDir>
#include <QSettings>
#include <QStandardPaths>

#include <system_error>

#include "graph/atomic_write.h"
#include "graph/errors.h"
#include "graph/graph_file.h"

namespace tfd::ui {

namespace {
constexpr const char* kRecentKey = "recentFiles";
constexpr int kDefaultIntervalMs = 30000;

bool removeQuietly(const std::filesystem::path& p) {
  std::error_code ec;
  return !p.empty() && std::filesystem::remove(p, ec);
}
}  // namespace

DocumentFiles::DocumentFiles(GraphDocument& document, QObject* parent)
    : QObject(parent), document_(document) {
  timer_.setInterval(kDefaultIntervalMs);
  connect(&timer_, &QTimer::timeout, this, &DocumentFiles::autosaveNow);
  timer_.start();
}

std::filesystem::path DocumentFiles::autosavePath(const std::filesystem::path& file) {
  if (file.empty()) {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
    QDir().mkpath(dir);
    return std::filesystem::path(dir.toStdString()) / "untitled.tfd.json.autosave";
  }
  return file.parent_path() / ("." + file.filename().string() + ".autosave");
}

void DocumentFiles::setAutosaveInterval(int ms) { timer_.setInterval(ms); }

bool DocumentFiles::autosaveNow() {
  if (!document_.isDirty() || document_.revision() == autosavedRevision_) return false;
  const std::filesystem::path side = autosavePath(document_.filePath());
  try {
    graph::writeTextFileAtomically(side, document_.text());
  } catch (const std::exception&) {
    return false;  // a read-only folder: no autosave, nothing else to do
  }
  if (autosaved_ != side) removeQuietly(autosaved_);
  autosaved_ = side;
  autosavedRevision_ = document_.revision();
  return true;
}

void DocumentFiles::discardAutosave() {
  removeQuietly(autosaved_);
  autosaved_.clear();
  autosavedRevision_ = 0;
}

void DocumentFiles::open(const std::filesystem::path& path) {
  document_.open(path);
  autosaved_.clear();
  autosavedRevision_ = document_.revision();
  addRecent(path);
}

void DocumentFiles::save(const std::filesystem::path& path) {
  document_.save(path);
  discardAutosave();
  removeQuietly(autosavePath(path));
  autosavedRevision_ = document_.revision();
  addRecent(path);
}

std::optional<std::filesystem::path> DocumentFiles::recoverable(
    const std::filesystem::path& file) const {
  const std::filesystem::path side = autosavePath(file);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(side, ec)) return std::nullopt;
  try {
    const std::string saved = file.empty() ? std::string() : graph::readTextFile(file);
    if (graph::readTextFile(side) != saved) return side;
  } catch (const std::exception&) {
    return side;  // the file itself is gone or unreadable: the autosave is all there is
  }
  removeQuietly(side);
  return std::nullopt;
}

void DocumentFiles::recover(const std::filesystem::path& autosave,
                            const std::filesystem::path& file) {
  graph::Graph g = graph::loadGraphFile(autosave, document_.registry());
  g.setSourcePath(file);
  document_.reset(std::move(g), file, true);
  autosaved_ = autosave;  // replaced by the next autosave, removed by the next save
  autosavedRevision_ = 0;
}

QStringList DocumentFiles::recentFiles() const {
  return QSettings().value(kRecentKey).toStringList();
}

void DocumentFiles::addRecent(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::path abs = std::filesystem::absolute(path, ec);
  const QString p = QString::fromStdString((ec ? path : abs).lexically_normal().string());
  QStringList list = recentFiles();
  list.removeAll(p);
  list.prepend(p);
  while (list.size() > kMaxRecent) list.removeLast();
  QSettings().setValue(kRecentKey, list);
  emit recentFilesChanged();
}

}  // namespace tfd::ui
