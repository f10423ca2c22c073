#include "render/renderer.h"

#include <stdexcept>
#include <vector>

#include "render/gl_api.h"
#include "render/shaders.h"

namespace tfd::render {

namespace {

GLuint compile(GLenum type, const char* source, std::string* error) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    if (error) *error = std::string("shader compilation failed: ") + log;
    glDeleteShader(s);
    return 0;
  }
  return s;
}

GLuint link(std::initializer_list<std::pair<GLenum, const char*>> stages, std::string* error) {
  GLuint p = glCreateProgram();
  std::vector<GLuint> shaders;
  for (auto [type, source] : stages) {
    GLuint s = compile(type, source, error);
    if (!s) {
      for (GLuint x : shaders) glDeleteShader(x);
      glDeleteProgram(p);
      return 0;
    }
    glAttachShader(p, s);
    shaders.push_back(s);
  }
  glLinkProgram(p);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    if (error) *error = std::string("shader linking failed: ") + log;
    glDeleteProgram(p);
    return 0;
  }
  return p;
}

/// A vertex array with a position buffer and a second attribute (normals or colours), and an
/// optional index buffer.
struct Batch {
  GLuint vao = 0, positions = 0, attribute = 0, indices = 0;
  GLsizei count = 0;
  bool indexed = false;
  float size = 1;

  void release() {
    if (vao) glDeleteVertexArrays(1, &vao);
    for (GLuint* b : {&positions, &attribute, &indices})
      if (*b) glDeleteBuffers(1, b);
    *this = Batch{};
  }
  void fill(const std::vector<float>& xyz, const void* second, std::size_t secondBytes,
            bool secondIsColour, const std::vector<std::uint32_t>* index) {
    release();
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &positions);
    glBindBuffer(GL_ARRAY_BUFFER, positions);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(xyz.size() * sizeof(float)), xyz.data(),
                 GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    glGenBuffers(1, &attribute);
    glBindBuffer(GL_ARRAY_BUFFER, attribute);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(secondBytes), second, GL_STATIC_DRAW);
    if (secondIsColour)
      glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, nullptr);
    else
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(1);
    if (index) {
      glGenBuffers(1, &indices);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(index->size() * sizeof(std::uint32_t)),
                   index->data(), GL_STATIC_DRAW);
      count = GLsizei(index->size());
      indexed = true;
    } else {
      count = GLsizei(xyz.size() / 3);
    }
    glBindVertexArray(0);
  }
  void draw(GLenum mode) const {
    if (!vao || count == 0) return;
    glBindVertexArray(vao);
    if (indexed)
      glDrawElements(mode, count, GL_UNSIGNED_INT, nullptr);
    else
      glDrawArrays(mode, 0, count);
  }
};

void setMatrix(GLuint program, const char* name, const Mat4& m) {
  const Eigen::Matrix4f f = m.cast<float>();
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, f.data());
}

}  // namespace

struct Renderer::Impl {
  GLuint surface = 0, colour = 0, lines = 0, points = 0;
  Batch boundary, slice, curves, overlay, traced, pointBatch, markers;
  std::array<float, 4> boundaryColour{};
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;

bool Renderer::initialized() const { return impl_->surface != 0; }

bool Renderer::initialize(std::string* error) {
  using namespace shaders;
  Impl& m = *impl_;
  m.surface =
      link({{GL_VERTEX_SHADER, kSurfaceVertex}, {GL_FRAGMENT_SHADER, kSurfaceFragment}}, error);
  m.colour =
      link({{GL_VERTEX_SHADER, kColourVertex}, {GL_FRAGMENT_SHADER, kColourFragment}}, error);
  m.lines = link({{GL_VERTEX_SHADER, kColourVertex},
                  {GL_GEOMETRY_SHADER, kLineGeometry},
                  {GL_FRAGMENT_SHADER, kLineFragment}},
                 error);
  m.points = link({{GL_VERTEX_SHADER, kPointVertex}, {GL_FRAGMENT_SHADER, kPointFragment}}, error);
  if (!m.surface || !m.colour || !m.lines || !m.points) {
    release();
    return false;
  }
  return true;
}

void Renderer::upload(const Scene& s) {
  Impl& m = *impl_;
  m.boundary.fill(s.boundary.positions, s.boundary.normals.data(),
                  s.boundary.normals.size() * sizeof(float), false, &s.boundary.indices);
  m.boundaryColour = s.boundary.colour;
  m.slice.fill(s.slice.positions, s.slice.colours.data(), s.slice.colours.size() * sizeof(Rgba),
               true, nullptr);
  auto lines = [](Batch& b, const LineSet& l) {
    b.fill(l.positions, l.colours.data(), l.colours.size() * sizeof(Rgba), true, nullptr);
    b.size = l.width;
  };
  lines(m.curves, s.curves);
  lines(m.overlay, s.overlay);
  lines(m.traced, s.lines);
  auto points = [](Batch& b, const PointSet& p) {
    b.fill(p.positions, p.colours.data(), p.colours.size() * sizeof(Rgba), true, nullptr);
    b.size = p.size;
  };
  points(m.pointBatch, s.points);
  points(m.markers, s.markers);
}

void Renderer::draw(const Camera& camera, int width, int height, const DrawOptions& o) {
  Impl& m = *impl_;
  if (!initialized()) return;
  glViewport(0, 0, width, height);
  if (o.clear) {
    glClearColor(o.background[0], o.background[1], o.background[2], o.background[3]);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  const Mat4 view = camera.view();
  const Mat4 mvp = camera.projection(double(width) / std::max(1, height)) * view;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_PROGRAM_POINT_SIZE);

  glUseProgram(m.colour);
  setMatrix(m.colour, "mvp", mvp);
  m.slice.draw(GL_TRIANGLES);

  glUseProgram(m.lines);
  setMatrix(m.lines, "mvp", mvp);
  glUniform2f(glGetUniformLocation(m.lines, "viewport"), float(width), float(height));
  for (const Batch* b : {&m.curves, &m.overlay, &m.traced}) {
    glUniform1f(glGetUniformLocation(m.lines, "width"), b->size);
    b->draw(GL_LINES);
  }

  glUseProgram(m.points);
  setMatrix(m.points, "mvp", mvp);
  glUniform1f(glGetUniformLocation(m.points, "size"), m.pointBatch.size);
  m.pointBatch.draw(GL_POINTS);

  if (o.showBoundary) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glUseProgram(m.surface);
    setMatrix(m.surface, "mvp", mvp);
    setMatrix(m.surface, "view", view);
    const auto& c = m.boundaryColour;
    glUniform4f(glGetUniformLocation(m.surface, "colour"), c[0], c[1], c[2], o.boundaryAlpha);
    m.boundary.draw(GL_TRIANGLES);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }

  glDisable(GL_DEPTH_TEST);
  glUseProgram(m.points);
  glUniform1f(glGetUniformLocation(m.points, "size"), m.markers.size);
  m.markers.draw(GL_POINTS);
  glEnable(GL_DEPTH_TEST);
  glBindVertexArray(0);
  glUseProgram(0);
}

void Renderer::release() {
  Impl& m = *impl_;
  for (Batch* b :
       {&m.boundary, &m.slice, &m.curves, &m.overlay, &m.traced, &m.pointBatch, &m.markers})
    b->release();
  for (GLuint* p : {&m.surface, &m.colour, &m.lines, &m.points})
    if (*p) {
      glDeleteProgram(*p);
      *p = 0;
    }
}

std::string Renderer::contextDescription() {
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

}  // namespace tfd::render
