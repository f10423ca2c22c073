#pragma once
// Small pages for a computation's fresh memory. `tfd` runs with transparent huge pages for its
// large arrays (README, "Huge pages"): a mesh's topology and a solver's hierarchy are read
// many times, where 2 MB pages save address translations. A topological edit instead fills
// some 200 MB of region-sized arrays at 1M tets that live for one cook, and on the virtual
// machines this project runs on a fresh huge page can cost 8 times more per MB than small
// pages (the host backs it when first touched; bench/standalone/fresh_pages.cpp measures it,
// bench/RESULTS.md "Small pages for an edit's fresh memory" has the figures).
//
// While a SmallPagesScope lives, page faults in this process take small pages (Linux
// prctl(PR_SET_THP_DISABLE)); memory already backed by huge pages keeps them. Scopes nest and
// may overlap across threads: the first to open sets the flag, the last to close restores what
// was there before (a process started with the flag set keeps it). Where the kernel has no
// such setting, a scope does nothing. Only speed depends on it, never a result.
namespace tfd::core {

class SmallPagesScope {
 public:
  SmallPagesScope();
  ~SmallPagesScope();
  SmallPagesScope(const SmallPagesScope&) = delete;
  SmallPagesScope& operator=(const SmallPagesScope&) = delete;
};

/// Whether page faults in this process take small pages now (false where unknown).
bool smallPagesOnly();

}  // namespace tfd::core
