#pragma once
// The Tab menu: every registered node type by category, filtered as you type (name, category
// or documentation), optionally only the types that can take a link being dragged. Enter or a
// click chooses. Everything comes from the registry, so new node types appear without edits.
#include <QFrame>

#include <optional>
#include <string_view>
#include <vector>

#include "graph/node_registry.h"
#include "ui/canvas/canvas_scene.h"

class QLineEdit;
class QTreeWidget;

namespace tfd::ui {

/// Node types whose name, category or doc contains `text` (case-insensitive) and, with `link`,
/// that have a port of the link's type on the other side; sorted by category, then name.
std::vector<const graph::NodeType*> matchingNodeTypes(const graph::NodeRegistry& registry,
                                                      std::string_view text,
                                                      const LinkStart* link = nullptr);

class NodeMenu : public QFrame {
  Q_OBJECT

 public:
  explicit NodeMenu(const graph::NodeRegistry& registry, QWidget* parent = nullptr);

  void setLinkFilter(std::optional<LinkStart> link);
  void setFilterText(const QString& text);
  /// Type names shown, in display order.
  QStringList visibleTypes() const;
  /// Opens at a global position with the search field focused and empty.
  void popupAt(QPoint globalPos);
  /// Chooses the highlighted type (the first match when none is). False when nothing matches.
  bool activateCurrent();

 signals:
  void typeChosen(const QString& type);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void rebuild();

  const graph::NodeRegistry& registry_;
  std::optional<LinkStart> link_;
  QLineEdit* search_;
  QTreeWidget* tree_;
};

}  // namespace tfd::ui
