#include "core/small_pages.h"

#include <sys/prctl.h>

#include <mutex>

namespace tfd::core {
namespace {

std::mutex scopesMutex;
int openScopes = 0;           // guarded by scopesMutex
bool setByTheScopes = false;  // the flag was clear before the first scope and set by it

}  // namespace

SmallPagesScope::SmallPagesScope() {
  const std::lock_guard lock(scopesMutex);
  if (openScopes++ == 0)
    setByTheScopes =
        prctl(PR_GET_THP_DISABLE, 0, 0, 0, 0) == 0 && prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0) == 0;
}

SmallPagesScope::~SmallPagesScope() {
  const std::lock_guard lock(scopesMutex);
  if (--openScopes == 0 && setByTheScopes) {
    prctl(PR_SET_THP_DISABLE, 0, 0, 0, 0);
    setByTheScopes = false;
  }
}

bool smallPagesOnly() { return prctl(PR_GET_THP_DISABLE, 0, 0, 0, 0) == 1; }

}  // namespace tfd::core
