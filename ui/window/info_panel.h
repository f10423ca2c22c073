#pragma once
// The info panel: the selected node's cook state, time and messages (info, warnings, errors),
// then every node of the last cook that has an error or a warning, so a failure elsewhere in
// the graph is never hidden. Reads the cook controller's statuses; holds nothing else.
#include <QTextBrowser>

#include <string>

#include "ui/cook/cook_controller.h"

namespace tfd::ui {

class InfoPanel : public QTextBrowser {
  Q_OBJECT

 public:
  InfoPanel(CookController& cook, QWidget* parent = nullptr);

  void setNode(const std::string& node);
  /// Rebuilds the text from the controller's statuses.
  void refresh();

 private:
  CookController& cook_;
  std::string node_;
};

}  // namespace tfd::ui
