#include "render/shaders.h"

namespace tfd::render::shaders {

// Boundary surface: translucent, lit from the eye, two-sided (|n.z| in view space).
const char* const kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 mvp;
uniform mat4 view;
out vec3 viewNormal;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  viewNormal = mat3(view) * normal;
})";

const char* const kSurfaceFragment = R"(#version 330 core
in vec3 viewNormal;
uniform vec4 colour;
out vec4 fragColour;
void main() {
  float facing = abs(normalize(viewNormal).z);
  // Silhouettes (grazing angles) a little more opaque, so the shape reads.
  float alpha = colour.a * (1.0 + 1.5 * (1.0 - facing));
  fragColour = vec4(colour.rgb * (0.45 + 0.55 * facing), clamp(alpha, 0.0, 0.9));
})";

// Per-vertex colours (cutting plane, lines).
const char* const kColourVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 mvp;
out vec4 vertexColour;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  vertexColour = colour;
})";

const char* const kColourFragment = R"(#version 330 core
in vec4 vertexColour;
out vec4 fragColour;
void main() { fragColour = vertexColour; })";

// Wide lines: each segment becomes a screen-aligned quad `width` pixels wide (core profile
// has no wide lines).
const char* const kLineGeometry = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 vertexColour[];
out vec4 fragColourIn;
uniform vec2 viewport;
uniform float width;
void main() {
  vec4 a = gl_in[0].gl_Position, b = gl_in[1].gl_Position;
  if (a.w <= 0.0 || b.w <= 0.0) return;
  vec2 sa = a.xy / a.w * viewport, sb = b.xy / b.w * viewport;
  vec2 d = sb - sa;
  if (dot(d, d) < 1e-12) d = vec2(1.0, 0.0);
  vec2 n = normalize(vec2(-d.y, d.x)) * width / viewport;
  // The same pixel offset at either end: scale by w back into clip space.
  gl_Position = vec4(a.xy + n * a.w, a.zw); fragColourIn = vertexColour[0]; EmitVertex();
  gl_Position = vec4(a.xy - n * a.w, a.zw); fragColourIn = vertexColour[0]; EmitVertex();
  gl_Position = vec4(b.xy + n * b.w, b.zw); fragColourIn = vertexColour[1]; EmitVertex();
  gl_Position = vec4(b.xy - n * b.w, b.zw); fragColourIn = vertexColour[1]; EmitVertex();
  EndPrimitive();
})";

const char* const kLineFragment = R"(#version 330 core
in vec4 fragColourIn;
out vec4 fragColour;
void main() { fragColour = fragColourIn; })";

const char* const kPointVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 mvp;
uniform float size;
out vec4 vertexColour;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  gl_PointSize = size;
  vertexColour = colour;
})";

// Round points with a dark rim.
const char* const kPointFragment = R"(#version 330 core
in vec4 vertexColour;
out vec4 fragColour;
void main() {
  vec2 c = gl_PointCoord * 2.0 - 1.0;
  float r = dot(c, c);
  if (r > 1.0) discard;
  fragColour = r > 0.6 ? vec4(0.05, 0.05, 0.05, 1.0) : vertexColour;
})";

}  // namespace tfd::render::shaders
