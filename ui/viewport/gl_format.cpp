#include "ui/viewport/gl_format.h"

namespace tfd::ui {

QSurfaceFormat viewportSurfaceFormat() {
  QSurfaceFormat f;
  f.setRenderableType(QSurfaceFormat::OpenGL);
  f.setVersion(3, 3);
  f.setProfile(QSurfaceFormat::CoreProfile);
  f.setDepthBufferSize(24);
  f.setSamples(4);
  return f;
}

}  // namespace tfd::ui
