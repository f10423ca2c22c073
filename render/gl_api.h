#pragma once
// OpenGL 3.3 core entry points, linked directly from GLVND's libOpenGL (which dispatches to
// whatever context is current: the editor's GLX context under X, or a surfaceless EGL context).
// Include only from render/*.cpp.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
