#pragma once
// The editor's document: one graph::Graph, the single source of truth, edited only through
// undoable commands (QUndoStack). Views (canvas, parameter panel, viewport) never keep a copy:
// they read graph() and refresh on changed().
//
// Every edit is validated by the graph layer on a copy first; a refused edit (a type-mismatched
// link, an out-of-range value, a cycle...) changes nothing, pushes no undo step, returns false
// (or an empty name) and reports the reason through lastError() and editRefused(). An accepted
// edit emits aboutToChange() before the graph changes (the cook controller cancels the running
// cook there) and changed() after; undo and redo do the same. Undo restores the exact earlier
// graph, so undo/redo round-trips give byte-identical files.
#include <QObject>
#include <QPointF>
#include <QString>
#include <QUndoStack>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"

namespace tfd::ui {

/// What an edit touched (flags of GraphDocument::changed).
enum ChangeFlag : int {
  kStructureChanged = 1,  ///< nodes or links added, removed or renamed
  kParamsChanged = 2,     ///< parameter values (cooking depends on them)
  kUiChanged = 4,         ///< positions, display flag (no re-cook needed, except display)
  kDocumentReplaced = 8,  ///< new / open: everything
};

class GraphDocument : public QObject {
  Q_OBJECT

 public:
  explicit GraphDocument(const graph::NodeRegistry& registry, QObject* parent = nullptr);
  ~GraphDocument() override;

  const graph::Graph& graph() const { return graph_; }
  const graph::NodeRegistry& registry() const { return graph_.registry(); }
  QUndoStack* undoStack() { return &undo_; }
  /// Incremented by every change, including undo and redo.
  std::uint64_t revision() const { return revision_; }
  /// The reason of the last refused edit.
  const std::string& lastError() const { return lastError_; }

  // ---- edits: one undo step each
  /// Adds a node at a canvas position; returns its name, or "" when refused.
  std::string addNode(std::string_view type, QPointF position = {}, std::string_view name = {});
  /// Removes the nodes (with their links) and the given links, as one step.
  bool remove(const std::vector<std::string>& nodes, const std::vector<graph::Link>& links = {});
  /// Links an output to an input. A link already in a single input is replaced (one step).
  bool connect(const graph::Endpoint& from, const graph::Endpoint& to);
  bool disconnect(const graph::Endpoint& from, const graph::Endpoint& to);
  /// Moves the input end of an existing link to `newTo`, or removes the link when `newTo` is
  /// empty (a link picked up from an input and dropped elsewhere), as one step.
  bool relink(const graph::Link& old, const std::optional<graph::Endpoint>& newTo);
  /// Adds a node and links it to `other` (an output when `otherIsOutput`, else an input)
  /// through its first compatible port, as one step (a link dropped on empty space).
  std::string addNodeLinked(std::string_view type, QPointF position, const graph::Endpoint& other,
                            bool otherIsOutput);
  /// Would connect() accept this link? (Changes nothing.)
  bool canConnect(const graph::Endpoint& from, const graph::Endpoint& to) const;
  /// Sets a parameter. `continuous` edits of the same parameter (a slider scrub) merge into one
  /// undo step until closeContinuousEdit().
  bool setParam(std::string_view node, std::string_view param, graph::ParamValue value,
                bool continuous = false);
  void closeContinuousEdit();
  bool resetParam(std::string_view node, std::string_view param);
  /// Moves several nodes as one step (the end of a drag).
  bool moveNodes(const std::map<std::string, QPointF>& positions);
  bool renameNode(std::string_view from, std::string_view to);
  /// Puts the display flag on `node` (and takes it off every other node); "" clears it.
  bool setDisplayNode(std::string_view node);

  // ---- clipboard: the file format's JSON text
  /// The nodes (in document order) and the links between them, as a graph file's text.
  std::string copyText(const std::vector<std::string>& nodes) const;
  /// Adds the nodes of a graph text (renamed where names are taken, moved by `offset`) with
  /// their links, as one step. Returns the new names (empty when refused).
  std::vector<std::string> paste(std::string_view text, QPointF offset = {});
  std::vector<std::string> duplicate(const std::vector<std::string>& nodes,
                                     QPointF offset = {40, 40});

  // ---- files
  /// An empty graph; clears the undo history.
  void newDocument();
  /// Replaces the document (clears the undo history). Throws graph::GraphError (LoadError).
  void open(const std::filesystem::path& path);
  /// Replaces the document with a graph given directly (e.g. a recovered autosave).
  void reset(graph::Graph graph, const std::filesystem::path& path, bool dirty);
  /// Writes the canonical text atomically and marks the document clean. Throws GraphError.
  void save(const std::filesystem::path& path);
  const std::filesystem::path& filePath() const { return path_; }
  bool isDirty() const { return !undo_.isClean(); }
  /// The canonical file text of the current graph.
  std::string text() const;

  /// Applies a snapshot (for the undo commands only).
  void applySnapshot(const graph::Graph& graph, int flags);

 signals:
  /// Before an accepted edit, undo or redo changes the graph (flags: what will change).
  void aboutToChange(int flags);
  void changed(int flags);
  void editRefused(const QString& message);
  /// The file path or the dirty state changed.
  void fileStateChanged();

 private:
  /// Runs `mutate` on a copy; on success pushes one undo step. Returns false when it threw.
  bool edit(const QString& text, int flags, const std::function<void(graph::Graph&)>& mutate,
            int mergeId = -1, std::string mergeKey = {});
  bool refuse(const std::string& message);

  graph::Graph graph_;
  QUndoStack undo_;
  std::filesystem::path path_;
  std::uint64_t revision_ = 0;
  std::string lastError_;
};

}  // namespace tfd::ui
