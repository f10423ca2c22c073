#include "core/edit/removal_scenario.h"

#include <cstdio>
#include <optional>

namespace tfd::core {
namespace {

/// The first non-transition pattern from one end (forward) or the other (backward).
std::optional<DegeneratePattern> endPattern(const DegenerateCurve& c, bool fromStart) {
  const std::size_t n = c.patterns.size();
  for (std::size_t k = 0; k < n; ++k) {
    const DegeneratePattern p = c.patterns[fromStart ? k : n - 1 - k];
    if (p != DegeneratePattern::Transition) return p;
  }
  return std::nullopt;
}

std::string pure(const PatternCounts& c) {
  if (c.wedge > 0 && c.trisector == 0) return "wedge";
  if (c.trisector > 0 && c.wedge == 0) return "trisector";
  return "";
}

}  // namespace

const char* toString(RemovalScenario s) {
  switch (s) {
    case RemovalScenario::OneCurve:
      return "one-curve";
    case RemovalScenario::TwoCurve:
      return "two-curve";
    case RemovalScenario::OneLoop:
      return "one-loop";
    case RemovalScenario::TwoLoop:
      return "two-loop";
  }
  return "?";
}

PatternCounts patternCounts(const DegenerateCurve& curve) {
  PatternCounts c;
  for (DegeneratePattern p : curve.patterns) {
    c.wedge += p == DegeneratePattern::Wedge;
    c.trisector += p == DegeneratePattern::Trisector;
  }
  return c;
}

std::string describeCurve(const DegenerateCurve& curve) {
  const Vec3 p = curve.points.empty() ? Vec3::Zero() : curve.points[curve.points.size() / 2];
  char buf[160];
  std::snprintf(buf, sizeof buf, "the %s %s through (%.3g, %.3g, %.3g)", toString(curve.type),
                curve.closed ? "loop" : "curve", p.x(), p.y(), p.z());
  return buf;
}

RemovalScenario removalScenario(std::span<const DegenerateCurve* const> targets) {
  if (targets.empty() || targets.size() > 2)
    throw RemovalRefused("pick one or two curves (got " + std::to_string(targets.size()) + ")");
  if (targets.size() == 1) {
    const DegenerateCurve& c = *targets[0];
    const PatternCounts n = patternCounts(c);
    const std::string what = describeCurve(c);
    if (c.closed) {
      if (n.wedge > 0 && n.trisector > 0) return RemovalScenario::OneLoop;
      throw RemovalRefused(what + " is a pure " + (n.wedge > 0 ? "wedge" : "trisector") +
                           " loop: it cannot be removed alone (it cancels only with a pure " +
                           (n.wedge > 0 ? "trisector" : "wedge") +
                           " loop of the same type: pick both, the two-loop removal)");
    }
    const auto a = endPattern(c, true), b = endPattern(c, false);
    if (a && b && *a != *b) return RemovalScenario::OneCurve;
    if (!pure(n).empty())
      throw RemovalRefused(what + " is a pure " + pure(n) +
                           " curve: it cannot be removed alone; pick it together with an open " +
                           (pure(n) == "wedge" ? "trisector" : "wedge") +
                           " curve of the same type (two-curve removal)");
    throw RemovalRefused(what + " has " + (a ? toString(*a) : "transition") +
                         " patterns at both ends: one-curve removal needs a wedge end and a "
                         "trisector end");
  }
  const DegenerateCurve &c0 = *targets[0], &c1 = *targets[1];
  const std::string both = describeCurve(c0) + " and " + describeCurve(c1);
  if (c0.closed && c1.closed) {
    const std::string p0 = pure(patternCounts(c0)), p1 = pure(patternCounts(c1));
    if (c0.type == c1.type && !p0.empty() && !p1.empty() && p0 != p1)
      return RemovalScenario::TwoLoop;
    throw RemovalRefused("cannot remove " + both +
                         " together: two-loop removal cancels a pure wedge loop with a pure "
                         "trisector loop of the same L/P type (these are " +
                         std::string(toString(c0.type)) + " " + (p0.empty() ? "mixed" : p0) +
                         " and " + toString(c1.type) + " " + (p1.empty() ? "mixed" : p1) + ")");
  }
  if (c0.closed || c1.closed)
    throw RemovalRefused("cannot remove " + both +
                         " together: two-curve removal takes two open curves, two-loop removal "
                         "two loops (a loop is removed alone, one-loop removal, when it has "
                         "wedge and trisector parts)");
  if (c0.type != c1.type)
    throw RemovalRefused("cannot remove " + both +
                         " together: two-curve removal needs two curves of the same L/P type");
  const std::string p0 = pure(patternCounts(c0)), p1 = pure(patternCounts(c1));
  if (p0.empty() || p1.empty() || p0 == p1)
    throw RemovalRefused("cannot remove " + both +
                         " together: two-curve removal cancels a pure wedge curve with a pure "
                         "trisector curve (these are " +
                         (p0.empty() ? "mixed" : p0) + " and " + (p1.empty() ? "mixed" : p1) + ")");
  return RemovalScenario::TwoCurve;
}

}  // namespace tfd::core
