#include "core/topology/tet_connection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tfd::core::topology {
namespace {

void pairGreedily(const TetLinearField& field, std::span<const TetNode> nodes, TetConnection& out) {
  std::vector<bool> used(nodes.size(), false);
  while (true) {
    int bi = -1, bj = -1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (used[i]) continue;
      for (std::size_t j = i + 1; j < nodes.size(); ++j) {
        if (used[j]) continue;
        const double d = (nodes[i].position - nodes[j].position).squaredNorm();
        if (d < best) best = d, bi = int(i), bj = int(j);
      }
    }
    if (bi < 0) break;
    used[bi] = used[bj] = true;
    TetSegment s;
    s.from = nodes[bi].id, s.to = nodes[bj].id;
    s.arc = classifyChord(field, nodes[bi].position, nodes[bj].position, nodes[bi].eigenvector,
                          nodes[bj].eigenvector);
    out.segments.push_back(std::move(s));
  }
}

}  // namespace

TetConnection connectTet(const TetLinearField& field, std::span<const TetNode> nodes,
                         int extraSamples) {
  TetConnection out;
  const std::size_t n = nodes.size();
  if (n < 2) {
    if (n == 1 && nodes[0].faceInterior) out.flags |= kTetOdd;
    return out;
  }
  const TetConic conic(field);
  if (!conic.valid()) {
    if (n == 2) {
      TetSegment s;
      s.from = nodes[0].id, s.to = nodes[1].id;
      s.arc = classifyChord(field, nodes[0].position, nodes[1].position, nodes[0].eigenvector,
                            nodes[1].eigenvector);
      out.segments.push_back(std::move(s));
      return out;
    }
    out.flags |= kTetNonGeneric | kTetHeuristic;
    pairGreedily(field, nodes, out);
    if (n % 2 == 1) out.flags |= kTetOdd;
    return out;
  }

  struct Item {
    double theta;
    std::size_t index;
    double sigma;
  };
  std::vector<Item> items;
  bool offConic = false;
  items.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& v = nodes[i].eigenvector;
    offConic = offConic || conic.residual(v) > 1e-6;
    const double theta = conic.theta(v);
    items.push_back({theta, i, conic.point(theta).sigma});
  }
  std::sort(items.begin(), items.end(), [&](const Item& a, const Item& b) {
    return a.theta != b.theta ? a.theta < b.theta : nodes[a.index].id < nodes[b.index].id;
  });

  // Arcs between θ-consecutive points: inside iff the midpoint is inside.
  struct Arc {
    std::size_t a, b;
    double thetaA, thetaB;
  };
  std::vector<Arc> inside;
  bool ambiguous = false;
  for (std::size_t k = 0; k < n; ++k) {
    const Item& a = items[k];
    const Item& b = items[(k + 1) % n];
    const double thetaA = a.theta;
    const double thetaB = k + 1 < n ? b.theta : b.theta + 2 * std::numbers::pi;
    // θ is accurate to rounding even where the chart is compressed, so only equal angles are
    // ambiguous.
    if (!(thetaB > thetaA)) {
      ambiguous = true;
      continue;
    }
    // An arc through infinity changes the sign of α (= of σ): outside.
    if ((a.sigma > 0) != (b.sigma > 0)) continue;
    const ConicPoint mid = conic.point(0.5 * (thetaA + thetaB));
    if (!mid.finite) continue;
    const double minBary = field.barycentric(mid.position).minCoeff();
    if (std::abs(minBary) < 1e-12) ambiguous = true;
    if (minBary <= 0) continue;
    inside.push_back({a.index, b.index, thetaA, thetaB});
  }

  if (n == 2 && nodes[0].faceInterior && nodes[1].faceInterior) {
    // Two transversal crossings bound exactly one arc inside (no loop fits in a tet, note §2.2
    // fact 3), so they are joined whatever the conic says; the conic only supplies the arc for
    // classification, when it identifies it unambiguously (it may not when the eigenvector
    // hardly varies along the curve, e.g. fields constant along it).
    TetSegment s;
    if (inside.size() == 1 && !ambiguous) {
      const Arc& arc = inside[0];
      s.from = nodes[arc.a].id, s.to = nodes[arc.b].id;
      s.exactArc = true;
      s.arc = classifyArc(conic, arc.thetaA, arc.thetaB, nodes[arc.a].eigenvector,
                          nodes[arc.b].eigenvector, extraSamples);
    } else {
      s.from = nodes[0].id, s.to = nodes[1].id;
      s.arc = classifyChord(field, nodes[0].position, nodes[1].position, nodes[0].eigenvector,
                            nodes[1].eigenvector);
    }
    out.segments.push_back(std::move(s));
    return out;
  }

  if (ambiguous) out.flags |= kTetAmbiguous;
  if (offConic) out.flags |= kTetOffConic;
  std::vector<int> uses(n, 0);
  for (const Arc& arc : inside) {
    TetSegment s;
    s.from = nodes[arc.a].id, s.to = nodes[arc.b].id;
    s.exactArc = true;
    s.arc = classifyArc(conic, arc.thetaA, arc.thetaB, nodes[arc.a].eigenvector,
                        nodes[arc.b].eigenvector, extraSamples);
    out.segments.push_back(std::move(s));
    ++uses[arc.a], ++uses[arc.b];
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (nodes[i].faceInterior && uses[i] != 1) out.flags |= kTetOdd;
  }
  return out;
}

}  // namespace tfd::core::topology
