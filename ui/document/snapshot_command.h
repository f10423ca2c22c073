#pragma once
// The undo command of every document edit: the graph before and after (graphs are small values;
// restoring the exact earlier graph keeps node and link order, so undo is byte-exact).
#include <QUndoCommand>

#include <string>

#include "graph/graph.h"

namespace tfd::ui {

class GraphDocument;

class SnapshotCommand : public QUndoCommand {
 public:
  /// mergeId >= 0: consecutive commands with the same id and key merge while still open.
  SnapshotCommand(GraphDocument& document, const QString& text, graph::Graph before,
                  graph::Graph after, int flags, int mergeId, std::string mergeKey);

  void undo() override;
  void redo() override;
  int id() const override { return mergeId_; }
  bool mergeWith(const QUndoCommand* other) override;
  /// Stops further merging into this command (the end of a slider scrub).
  void close() { open_ = false; }

 private:
  GraphDocument& document_;
  graph::Graph before_, after_;
  int flags_;
  int mergeId_;
  std::string mergeKey_;
  bool open_ = true;
};

}  // namespace tfd::ui
