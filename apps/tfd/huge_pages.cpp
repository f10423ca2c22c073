#include "apps/tfd/huge_pages.h"

#include <unistd.h>

#include <cstdlib>

namespace tfd::cli {

void restartWithHugePages(char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  if (std::getenv("GLIBC_TUNABLES") != nullptr) return;  // set by the user, or restarted
  if (::setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  ::unsetenv("GLIBC_TUNABLES");  // exec failed: carry on without
#else
  (void)argv;
#endif
}

}  // namespace tfd::cli
