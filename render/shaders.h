#pragma once
// GLSL 3.30 core sources of the renderer's programs (shaders.cpp).
namespace tfd::render::shaders {

extern const char* const kSurfaceVertex;
extern const char* const kSurfaceFragment;
extern const char* const kColourVertex;
extern const char* const kColourFragment;
extern const char* const kLineGeometry;
extern const char* const kLineFragment;
extern const char* const kPointVertex;
extern const char* const kPointFragment;

}  // namespace tfd::render::shaders
