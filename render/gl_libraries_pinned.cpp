#include "render/gl_libraries_pinned.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TFD_ADDRESS_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define TFD_ADDRESS_SANITIZER 1
#endif

#ifdef TFD_ADDRESS_SANITIZER
// The executable's dlclose comes before the C library's for every library that calls it (the
// GL loaders among them): nothing is unloaded, the handle stays valid for a later dlopen.
extern "C" __attribute__((visibility("default"))) int dlclose(void*) { return 0; }
#endif

namespace tfd::render {

// Defined here, beside the dlclose above, so that every program creating a context links this
// file from the static library.
void pinGlLibrariesUnderSanitizers() {}

}  // namespace tfd::render
