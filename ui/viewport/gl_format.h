#pragma once
// The OpenGL context the viewport asks for: 3.3 core with a depth buffer and 4x multisampling
// (render/ is written against OpenGL 3.3 core). Set as the default before QApplication exists.
#include <QSurfaceFormat>

namespace tfd::ui {

QSurfaceFormat viewportSurfaceFormat();

}  // namespace tfd::ui
