// tfd-editor [GRAPH]: the Qt node editor (ui/window/main_window.h).
#include <QApplication>
#include <QSurfaceFormat>

#include "apps/tfd/huge_pages.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "ui/viewport/gl_format.h"
#include "ui/window/main_window.h"

int main(int argc, char** argv) {
  // A cook in the editor touches the same large arrays as one by `tfd` (README, "Huge pages").
  tfd::cli::restartWithHugePages(argv);
  QSurfaceFormat::setDefaultFormat(tfd::ui::viewportSurfaceFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("tfd");
  QApplication::setApplicationName("tfd-editor");
  tfd::graph::NodeRegistry registry;
  tfd::nodes::registerAll(registry);
  tfd::ui::MainWindow window(registry);
  window.show();
  const QStringList args = QApplication::arguments();
  if (args.size() > 1)
    window.openFile(args.at(1).toStdString());
  else
    window.offerUntitledRecovery();
  return QApplication::exec();
}
