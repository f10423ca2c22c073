#include "core/topology/curve_assembly.h"

#include <algorithm>

namespace tfd::core::topology {
namespace {

struct Step {
  int segment;
  bool forward;  ///< traversed from `from` to `to`
};

DegeneratePattern patternOf(double cosine) {
  if (cosine > 0) return DegeneratePattern::Wedge;
  if (cosine < 0) return DegeneratePattern::Trisector;
  return DegeneratePattern::Transition;
}

DegeneratePattern combine(double arriving, double leaving) {
  if (arriving > 0 && leaving > 0) return DegeneratePattern::Wedge;
  if (arriving < 0 && leaving < 0) return DegeneratePattern::Trisector;
  return DegeneratePattern::Transition;  // δ changes sign across the face (or vanishes there)
}

}  // namespace

AssemblyResult assembleCurves(const std::vector<CurveNode>& nodes,
                              const std::vector<AssemblySegment>& segments) {
  AssemblyResult result;
  const int nodeCount = int(nodes.size());
  std::vector<std::vector<int>> incident(nodeCount);
  for (int s = 0; s < int(segments.size()); ++s) {
    const AssemblySegment& seg = segments[s];
    if (seg.from == seg.to) continue;
    incident[seg.from].push_back(s);
    incident[seg.to].push_back(s);
  }
  for (const auto& inc : incident)
    if (inc.size() > 2) ++result.junctions;
  std::vector<char> visited(segments.size(), 0);
  for (int s = 0; s < int(segments.size()); ++s)
    if (segments[s].from == segments[s].to) visited[s] = 1;

  // Arc-end data of a step: cosine/tangent where the step starts and ends (in travel direction).
  const auto startCosine = [&](const Step& st) {
    const ArcClassification& a = segments[st.segment].arc;
    return st.forward ? a.start.cosine : a.end.cosine;
  };
  const auto endCosine = [&](const Step& st) {
    const ArcClassification& a = segments[st.segment].arc;
    return st.forward ? a.end.cosine : a.start.cosine;
  };
  const auto startTangent = [&](const Step& st) -> Vec3 {
    const ArcClassification& a = segments[st.segment].arc;
    return st.forward ? a.start.tangent : Vec3(-a.end.tangent);
  };
  const auto endTangent = [&](const Step& st) -> Vec3 {
    const ArcClassification& a = segments[st.segment].arc;
    return st.forward ? a.end.tangent : Vec3(-a.start.tangent);
  };

  const auto emit = [&](const std::vector<int>& chain, const std::vector<Step>& steps,
                        bool closed) {
    DegenerateCurve c;
    c.closed = closed;
    const std::size_t nodeSteps = closed ? steps.size() : chain.size();
    int linear = 0, planar = 0;
    for (std::size_t i = 0; i < nodeSteps; ++i) {
      const CurveNode& node = nodes[chain[i]];
      const Step* arriving = i > 0 ? &steps[i - 1] : (closed ? &steps.back() : nullptr);
      const Step* leaving = i < steps.size() ? &steps[i] : nullptr;
      DegeneratePattern pattern;
      Vec3 tangent = Vec3::Zero();
      if (arriving && leaving) {
        pattern = combine(endCosine(*arriving), startCosine(*leaving));
        tangent = endTangent(*arriving) + startTangent(*leaving);
      } else if (arriving) {
        pattern = patternOf(endCosine(*arriving));
        tangent = endTangent(*arriving);
      } else {
        pattern = patternOf(startCosine(*leaving));
        tangent = startTangent(*leaving);
      }
      if (tangent.norm() > 0) tangent.normalize();
      c.points.push_back(node.position);
      c.patterns.push_back(pattern);
      c.tangents.push_back(tangent);
      c.eigenvectors.push_back(node.eigenvector);
      c.sources.push_back(node.source);
      ++(node.sigma > 0 ? linear : planar);
      if (!leaving) break;
      const AssemblySegment& seg = segments[leaving->segment];
      const auto& interior = seg.arc.interior;
      for (std::size_t k = 0; k < interior.size(); ++k) {
        const ArcPoint& p = leaving->forward ? interior[k] : interior[interior.size() - 1 - k];
        c.points.push_back(p.position);
        c.patterns.push_back(p.transition ? DegeneratePattern::Transition : patternOf(p.cosine));
        c.tangents.push_back(leaving->forward ? p.tangent : Vec3(-p.tangent));
        c.eigenvectors.push_back(p.eigenvector);
        c.sources.push_back({PointSource::Kind::Tet, seg.tet});
      }
    }
    c.type = linear >= planar ? DegenerateType::Linear : DegenerateType::Planar;
    if (linear > 0 && planar > 0) ++result.mixedTypeCurves;
    if (!closed) {
      if (!nodes[chain.front()].onBoundary) ++result.danglingEnds;
      if (!nodes[chain.back()].onBoundary) ++result.danglingEnds;
    }
    result.curves.push_back(std::move(c));
  };

  const auto walk = [&](int start, int firstSegment) {
    std::vector<int> chain{start};
    std::vector<Step> steps;
    int current = start, seg = firstSegment;
    bool closed = false;
    while (seg >= 0) {
      visited[seg] = 1;
      const bool forward = segments[seg].from == current;
      steps.push_back({seg, forward});
      current = forward ? segments[seg].to : segments[seg].from;
      if (current == start) {
        closed = true;
        break;
      }
      chain.push_back(current);
      if (incident[current].size() != 2) break;
      seg = -1;
      for (int s : incident[current])
        if (!visited[s]) seg = s;
    }
    emit(chain, steps, closed);
  };

  for (int n = 0; n < nodeCount; ++n) {
    if (incident[n].size() == 2) continue;
    for (int s : incident[n])
      if (!visited[s]) walk(n, s);
  }
  for (int s = 0; s < int(segments.size()); ++s) {
    if (!visited[s]) walk(segments[s].from, s);
  }
  return result;
}

}  // namespace tfd::core::topology
