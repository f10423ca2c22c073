#pragma once
// Which removal of paper §6.4 (Fig. 17) applies to the curves a user picked:
//  - one-curve: one open curve whose two ends are of opposite pattern (wedge / trisector);
//  - two-curve: an open pure wedge curve and an open pure trisector curve of the same L/P type;
//  - one-loop: one loop with both wedge and trisector parts;
//  - two-loop: a pure wedge loop and a pure trisector loop of the same L/P type.
// For the first three the enclosing region is a ball (§6.4); for two loops it is a solid torus,
// so the removal is the paper's composite: reconnect the loops into one mixed loop (§6.2), then
// remove that (remove_curves.h). Anything else is refused with the reason. Transition points
// are ignored when reading a curve's patterns.
#include <span>
#include <string>

#include "core/error.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

enum class RemovalScenario { OneCurve, TwoCurve, OneLoop, TwoLoop };
/// "one-curve", "two-curve", "one-loop", "two-loop"
const char* toString(RemovalScenario scenario);

/// A pick the removal cannot do (no scenario applies, no ball region avoids the other curves):
/// the user's input is at fault, not the algorithm.
class RemovalRefused : public Error {
 public:
  using Error::Error;
};

/// The scenario of the distinct picked curves (one or two). Throws RemovalRefused with the
/// reason, naming the curves by position.
RemovalScenario removalScenario(std::span<const DegenerateCurve* const> targets);

/// "the linear loop through (0.4, 0, 0.01)": a curve named by type, shape and a point on it.
std::string describeCurve(const DegenerateCurve& curve);

/// Wedge and trisector point counts of a curve (transition points excluded).
struct PatternCounts {
  int wedge = 0, trisector = 0;
};
PatternCounts patternCounts(const DegenerateCurve& curve);

}  // namespace tfd::core
