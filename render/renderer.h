#pragma once
// Draws a Scene with OpenGL 3.3 core into the currently bound framebuffer: the cutting plane,
// lines and points opaque with depth, then the boundary translucent over them, then markers on
// top. Used by the editor's viewport (inside QOpenGLWidget::paintGL) and by `tfd render`
// (a surfaceless EGL context, headless.h). Every method needs the context current; call
// release() before the context goes away.
#include <array>
#include <memory>
#include <string>

#include "render/camera.h"
#include "render/scene.h"

namespace tfd::render {

struct DrawOptions {
  std::array<float, 4> background{0.15f, 0.16f, 0.18f, 1.0f};
  bool clear = true;
  bool showBoundary = true;
  float boundaryAlpha = 0.18f;
};

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Compiles the programs. Returns false with a reason (e.g. no OpenGL 3.3).
  bool initialize(std::string* error);
  bool initialized() const;
  /// Copies the scene's arrays into GPU buffers (replacing the previous scene).
  void upload(const Scene& scene);
  /// Draws the uploaded scene.
  void draw(const Camera& camera, int width, int height, const DrawOptions& options = {});
  /// Frees the GPU objects (context current).
  void release();
  /// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5" or similar.
  static std::string contextDescription();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tfd::render
