#pragma once
// Under AddressSanitizer, keeps the OpenGL driver libraries loaded until the process exits.
//
// Mesa's software driver keeps a few small blocks from the first draw call in its own globals
// (valgrind --keep-debuginfo=yes on tfd_test_render_headless: 3 × (56 + 56) bytes, calloc'd
// inside swrast_dri.so under Renderer::draw). The GL loaders (libEGL, libGLX) unload the driver
// with dlclose when the last display goes; its globals vanish with it, and at exit LeakSanitizer
// reports those blocks as leaked by an "<unknown module>", which no suppression can name. With
// the driver kept loaded they stay reachable, and a leak of ours in the same program still
// fails it.

namespace tfd::render {

/// Call before creating an OpenGL context. Does nothing in a build without AddressSanitizer.
void pinGlLibrariesUnderSanitizers();

}  // namespace tfd::render
