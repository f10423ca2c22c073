#pragma once
// The 3D view: a QOpenGLWidget drawing a render::Scene with render::Renderer (the code
// `tfd render` uses). Left drag orbits, middle drag (or Shift + left) pans, right drag and the
// wheel zoom, F frames the scene, 1/2/3/0 look along x, y, z or from the iso corner. A left
// click without a drag is reported as clicked() (picking is decided by the owner).
#include <QElapsedTimer>
#include <QOpenGLWidget>

#include <optional>

#include "render/camera.h"
#include "render/renderer.h"
#include "render/scene.h"

namespace tfd::ui {

class ViewportWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit ViewportWidget(QWidget* parent = nullptr);
  ~ViewportWidget() override;

  /// Replaces what is drawn (uploaded at the next frame). The camera frames the scene when it
  /// is the first non-empty one or `frame` is set; otherwise it stays where the user put it.
  void setScene(render::Scene scene, bool frame = false);
  const render::Scene& scene() const { return scene_; }
  render::Camera& camera() { return camera_; }
  void frameAll();
  void setView(render::ViewPreset preset);

  /// Frames drawn so far, and the wall time of the last one (paintGL, milliseconds).
  int framesDrawn() const { return frames_; }
  double lastFrameMilliseconds() const { return lastFrameMs_; }
  /// Frames drawn since the scene was last replaced (0: the current scene is not drawn yet).
  int framesOfCurrentScene() const { return framesOfScene_; }
  /// The OpenGL renderer ("llvmpipe ...") or why drawing is unavailable.
  const QString& glStatus() const { return glStatus_; }
  bool glReady() const { return renderer_.initialized(); }

 signals:
  void clicked(QPointF pixel);
  void frameDrawn();

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

 private:
  void releaseGl();

  render::Renderer renderer_;
  render::Scene scene_;
  render::Camera camera_;
  bool uploadPending_ = false, framed_ = false;
  std::optional<QPointF> pressAt_;
  QPointF lastPos_;
  bool dragged_ = false;
  int frames_ = 0, framesOfScene_ = 0;
  double lastFrameMs_ = 0;
  QString glStatus_ = "OpenGL not initialised yet";
};

}  // namespace tfd::ui
