#include "render/headless.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>

#include "render/gl_api.h"
#include "render/gl_libraries_pinned.h"

namespace tfd::render {

struct HeadlessContext::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("headless OpenGL: " + what + " (EGL error 0x" + [] {
    char b[16];
    std::snprintf(b, sizeof b, "%04x", eglGetError());
    return std::string(b);
  }() + ")");
}

EGLDisplay surfacelessDisplay() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) fail("eglGetPlatformDisplayEXT is missing (EGL_EXT_platform_base)");
  EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) fail("no surfaceless EGL display (is libegl-mesa0 installed?)");
  return d;
}

}  // namespace

HeadlessContext::HeadlessContext(int width, int height)
    : egl_(std::make_unique<Egl>()), width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::runtime_error("headless OpenGL: size " + std::to_string(width) + "x" +
                             std::to_string(height) + " is outside 1..16384");
  pinGlLibrariesUnderSanitizers();
  egl_->display = surfacelessDisplay();
  EGLint major = 0, minor = 0;
  if (!eglInitialize(egl_->display, &major, &minor)) fail("eglInitialize failed");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("desktop OpenGL is not available through EGL");
  // The surfaceless platform has no window configs (eglChooseConfig's default surface type);
  // we draw into our own framebuffer object, so any config (or none) will do.
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_RENDERABLE_TYPE,
                                  EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(egl_->display, configAttribs, &config, 1, &count) || count < 1)
    config = nullptr;  // EGL_KHR_no_config_context (Mesa has it)
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   3,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
  egl_->context = eglCreateContext(egl_->display, config, EGL_NO_CONTEXT, contextAttribs);
  if (egl_->context == EGL_NO_CONTEXT) fail("cannot create an OpenGL 3.3 core context");
  if (!eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context))
    fail("cannot make the context current without a surface");

  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  const GLsizei samples = std::min<GLint>(4, maxSamples);
  glGenFramebuffers(1, &msFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, msFbo_);
  glGenRenderbuffers(1, &msColour_);
  glBindRenderbuffer(GL_RENDERBUFFER, msColour_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msColour_);
  glGenRenderbuffers(1, &msDepth_);
  glBindRenderbuffer(GL_RENDERBUFFER, msDepth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msDepth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("headless OpenGL: multisampled framebuffer incomplete");
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("headless OpenGL: framebuffer incomplete");
  bind();
}

HeadlessContext::~HeadlessContext() {
  if (egl_->context != EGL_NO_CONTEXT) {
    glDeleteFramebuffers(1, &msFbo_);
    glDeleteFramebuffers(1, &fbo_);
    GLuint rb[3] = {msColour_, msDepth_, colour_};
    glDeleteRenderbuffers(3, rb);
    eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(egl_->display, egl_->context);
  }
  if (egl_->display != EGL_NO_DISPLAY) eglTerminate(egl_->display);
}

void HeadlessContext::bind() { glBindFramebuffer(GL_FRAMEBUFFER, msFbo_); }

void HeadlessContext::finish() { glFinish(); }

Image HeadlessContext::read() {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  Image image;
  image.width = width_;
  image.height = height_;
  image.rgba.resize(std::size_t(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> flipped(image.rgba.size());
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
  const std::size_t row = std::size_t(width_) * 4;
  for (int y = 0; y < height_; ++y)  // OpenGL's first row is the bottom one
    std::copy_n(&flipped[std::size_t(height_ - 1 - y) * row], row,
                &image.rgba[std::size_t(y) * row]);
  bind();
  return image;
}

Image renderImage(const Scene& scene, const RenderRequest& request) {
  HeadlessContext context(request.width, request.height);
  Renderer renderer;
  std::string error;
  if (!renderer.initialize(&error)) throw std::runtime_error("headless OpenGL: " + error);
  renderer.upload(scene);
  Camera camera;
  camera.setPreset(request.view);
  camera.frame(scene.bounds.valid() ? scene.bounds : Bounds{Vec3(-1, -1, -1), Vec3(1, 1, 1)},
               double(request.width) / request.height);
  context.bind();
  renderer.draw(camera, request.width, request.height, request.draw);
  Image image = context.read();
  renderer.release();
  return image;
}

}  // namespace tfd::render
