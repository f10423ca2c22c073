#include "ui/document/snapshot_command.h"

#include "ui/document/graph_document.h"

namespace tfd::ui {

SnapshotCommand::SnapshotCommand(GraphDocument& document, const QString& text, graph::Graph before,
                                 graph::Graph after, int flags, int mergeId, std::string mergeKey)
    : QUndoCommand(text),
      document_(document),
      before_(std::move(before)),
      after_(std::move(after)),
      flags_(flags),
      mergeId_(mergeId),
      mergeKey_(std::move(mergeKey)) {}

void SnapshotCommand::undo() { document_.applySnapshot(before_, flags_); }

void SnapshotCommand::redo() { document_.applySnapshot(after_, flags_); }

bool SnapshotCommand::mergeWith(const QUndoCommand* other) {
  const auto* o = dynamic_cast<const SnapshotCommand*>(other);
  if (!o || !open_ || o->mergeId_ != mergeId_ || o->mergeKey_ != mergeKey_) return false;
  after_ = o->after_;
  flags_ |= o->flags_;
  return true;
}

}  // namespace tfd::ui
