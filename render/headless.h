#pragma once
// Drawing without a display: a surfaceless EGL context on Mesa (no X server needed; llvmpipe
// when there is no GPU) rendering into a 4x multisampled framebuffer object, read back as an
// Image. Used by `tfd render`, the render tests and the frame-time benchmark.
#include <memory>
#include <string>

#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"
#include "render/scene.h"

namespace tfd::render {

class HeadlessContext {
 public:
  /// A current OpenGL 3.3 core context with a width x height target. Throws std::runtime_error
  /// saying what is missing (no EGL display, no surfaceless platform, no 3.3 core context).
  HeadlessContext(int width, int height);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  /// Binds the multisampled target (draw into it, then read()).
  void bind();
  /// Resolves the samples and reads the pixels (top row first).
  Image read();
  /// Waits for the GPU (for timing).
  void finish();

 private:
  struct Egl;
  std::unique_ptr<Egl> egl_;
  int width_, height_;
  unsigned msFbo_ = 0, msColour_ = 0, msDepth_ = 0, fbo_ = 0, colour_ = 0;
};

struct RenderRequest {
  int width = 1024, height = 768;
  ViewPreset view = ViewPreset::Iso;
  DrawOptions draw{};
};

/// Draws a scene framed to its bounds from a preset view. Throws std::runtime_error.
Image renderImage(const Scene& scene, const RenderRequest& request);

}  // namespace tfd::render
