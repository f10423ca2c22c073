#include "ui/viewport/viewport_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include <cmath>
#include <string>

#include "render/gl_libraries_pinned.h"

namespace tfd::ui {

namespace {
constexpr double kClickSlop = 4;  // pixels a click may move and still be a click
}

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
  render::pinGlLibrariesUnderSanitizers();
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(200, 150);
  setMouseTracking(false);
}

ViewportWidget::~ViewportWidget() { releaseGl(); }

void ViewportWidget::releaseGl() {
  if (!context()) return;
  makeCurrent();
  renderer_.release();
  doneCurrent();
}

void ViewportWidget::initializeGL() {
  // The context is re-created when the widget moves to another window: release with it.
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseGl,
          Qt::UniqueConnection);
  std::string error;
  if (renderer_.initialize(&error)) {
    glStatus_ = QString::fromStdString(render::Renderer::contextDescription());
  } else {
    glStatus_ = "OpenGL 3.3 core unavailable: " + QString::fromStdString(error);
  }
  uploadPending_ = true;
}

void ViewportWidget::setScene(render::Scene scene, bool frame) {
  scene_ = std::move(scene);
  uploadPending_ = true;
  framesOfScene_ = 0;
  if (frame || (!framed_ && !scene_.empty())) frameAll();
  update();
}

void ViewportWidget::frameAll() {
  if (!scene_.bounds.valid()) return;
  camera_.frame(scene_.bounds, double(width()) / std::max(1, height()));
  framed_ = true;
  update();
}

void ViewportWidget::setView(render::ViewPreset preset) {
  camera_.setPreset(preset);
  frameAll();
}

void ViewportWidget::paintGL() {
  QElapsedTimer timer;
  timer.start();
  if (!renderer_.initialized()) return;
  if (uploadPending_) {
    renderer_.upload(scene_);
    uploadPending_ = false;
  }
  const qreal dpr = devicePixelRatioF();
  renderer_.draw(camera_, int(std::lround(width() * dpr)), int(std::lround(height() * dpr)));
  lastFrameMs_ = double(timer.nsecsElapsed()) * 1e-6;
  ++frames_;
  ++framesOfScene_;
  emit frameDrawn();
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  pressAt_ = event->position();
  lastPos_ = event->position();
  dragged_ = false;
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  if (!pressAt_) return;
  const QPointF d = event->position() - lastPos_;
  lastPos_ = event->position();
  if (!dragged_ && (event->position() - *pressAt_).manhattanLength() <= kClickSlop) return;
  dragged_ = true;
  const Qt::MouseButtons b = event->buttons();
  if ((b & Qt::MiddleButton) || ((b & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier)))
    camera_.pan(d.x(), d.y(), height());
  else if (b & Qt::LeftButton)
    camera_.orbit(d.x(), d.y());
  else if (b & Qt::RightButton)
    camera_.zoom(std::pow(1.01, -d.y()));
  update();
  event->accept();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (pressAt_ && !dragged_ && event->button() == Qt::LeftButton) emit clicked(event->position());
  pressAt_.reset();
  event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  camera_.zoom(std::pow(1.15, event->angleDelta().y() / 120.0));
  update();
  event->accept();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_F:
    case Qt::Key_Home:
      frameAll();
      return;
    case Qt::Key_0:
      setView(render::ViewPreset::Iso);
      return;
    case Qt::Key_1:
      setView(render::ViewPreset::X);
      return;
    case Qt::Key_2:
      setView(render::ViewPreset::Y);
      return;
    case Qt::Key_3:
      setView(render::ViewPreset::Z);
      return;
    default:
      QOpenGLWidget::keyPressEvent(event);
  }
}

}  // namespace tfd::ui
