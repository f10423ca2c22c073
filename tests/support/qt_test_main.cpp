// main() of the editor tests: a QApplication for widgets, then GoogleTest. Plain model and
// widget tests run with QT_QPA_PLATFORM=offscreen (set by ctest, and here when there is no X
// display, e.g. while ctest lists the tests at build time); OpenGL tests run under Xvfb.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSurfaceFormat>

#include "ui/viewport/gl_format.h"

int main(int argc, char** argv) {
  if (!qEnvironmentVariableIsSet("DISPLAY") && !qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QSurfaceFormat::setDefaultFormat(tfd::ui::viewportSurfaceFormat());
  QApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
