#include "core/surface/surface_orient.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace tfd::core {
namespace {

/// One side of a triangle: the undirected edge (lo, hi), the triangle, and whether the
/// triangle runs it from lo to hi.
struct Side {
  int lo, hi, tri;
  bool forward;
  bool operator<(const Side& o) const {
    return std::tie(lo, hi, tri) < std::tie(o.lo, o.hi, o.tri);
  }
};

}  // namespace

OrientReport orientConsistently(SurfaceMesh& mesh) {
  OrientReport report;
  const int n = int(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return report;  // for the check to name
  std::vector<Side> sides;
  sides.reserve(3 * std::size_t(n));
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(sides.begin(), sides.end());
  // Each triangle's three neighbours across its edges, with whether the pair runs the shared
  // edge the same way (then exactly one of the two must be reversed).
  struct Link {
    int other;
    bool same;
  };
  std::vector<std::array<Link, 3>> links(n);
  std::vector<int> filled(n, 0);
  for (std::size_t i = 0; i < sides.size(); i += 2) {
    if (i + 1 >= sides.size() || sides[i + 1].lo != sides[i].lo || sides[i + 1].hi != sides[i].hi ||
        (i + 2 < sides.size() && sides[i + 2].lo == sides[i].lo && sides[i + 2].hi == sides[i].hi))
      return report;  // an open or non-manifold edge: for the surface check to name
    const Side &a = sides[i], &b = sides[i + 1];
    const bool same = a.forward == b.forward;
    links[a.tri][filled[a.tri]++] = {b.tri, same};
    links[b.tri][filled[b.tri]++] = {a.tri, same};
  }
  // Breadth-first over each piece from its first triangle: flip[t] says whether t must be
  // reversed to agree with that triangle.
  std::vector<signed char> flip(n, -1);
  std::vector<int> piece;
  std::vector<int> toFlip;
  for (int start = 0; start < n; ++start) {
    if (flip[start] >= 0) continue;
    piece.assign(1, start);
    flip[start] = 0;
    std::size_t reversed = 0;
    for (std::size_t head = 0; head < piece.size(); ++head) {
      const int t = piece[head];
      for (const Link& l : links[t]) {
        const auto want = static_cast<signed char>(flip[t] ^ (l.same ? 1 : 0));
        if (flip[l.other] < 0) {
          flip[l.other] = want;
          reversed += want;
          piece.push_back(l.other);
        } else if (flip[l.other] != want) {
          report.oneSided = true;
          return report;
        }
      }
    }
    // Keep the orientation most of the piece has.
    const bool invert = 2 * reversed > piece.size();
    for (int t : piece)
      if (bool(flip[t]) != invert) toFlip.push_back(t);
  }
  for (int t : toFlip) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
  report.flippedTriangles = toFlip.size();
  report.applied = true;
  return report;
}

}  // namespace tfd::core
