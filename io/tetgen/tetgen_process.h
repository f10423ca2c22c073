#pragma once
// Runs TetGen in a child process, where it can be stopped. TetGen has no cancellation hook and
// some inputs send its refinement into a loop that runs for minutes; in a child process
// (fork) the caller polls its cancel flag, a time limit and the child's memory, and kills the
// child when any is exceeded. The child also means TetGen's global state (its predicates) is
// never shared: several meshes can be made at once.
#include <cstdint>
#include <string>
#include <vector>

#include "core/progress.h"

class tetgenio;

namespace tfd::io {

struct TetgenRunLimits {
  double seconds = 0;                            ///< wall-clock limit; 0: none
  std::uint64_t memoryBytes = 0;                 ///< resident memory of the child; 0: none
  std::string source;                            ///< names the input in messages ("file 'x.stl'")
  std::string timeLimitName = "the time limit";  ///< how the limit is set, for messages
};

/// What TetGen returned, or the code it failed with.
struct TetgenRun {
  int failureCode = 0;         ///< 0: success; else TetGen's error code (tetgen.h)
  std::string said;            ///< what TetGen printed (trimmed, one line, at most ~300 chars)
  std::vector<double> points;  ///< 3 per vertex
  std::vector<int> tets;       ///< 4 zero-based vertex indices per tet
};

/// Runs ::tetrahedralize(switches, in) in a forked child and returns its output. Throws
/// core::Cancelled when `progress` is cancelled (the child is killed within about 50 ms), and
/// core::Error naming limits.source when the time or memory limit is exceeded, when TetGen runs
/// out of memory, or when the child dies (crash, killed by the system).
TetgenRun runTetgenInChild(const std::string& switches, tetgenio& in, const TetgenRunLimits& limits,
                           const core::Progress& progress);

}  // namespace tfd::io
