#include "core/synth/element_shapes.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace tfd::core {
namespace {

using std::numbers::pi;

/// Closes a ring of `n` vertices starting at `first` with a fan around vertex `centre`, wound
/// like the ring, or against it with `reverse`.
void fan(SurfaceMesh& m, int centre, int first, int n, bool reverse) {
  for (int i = 0; i < n; ++i) {
    const int a = first + i, b = first + (i + 1) % n;
    m.triangles.push_back(reverse ? std::array<int, 3>{centre, b, a}
                                  : std::array<int, 3>{centre, a, b});
  }
}

/// Quads between two rings of `n` vertices (ring0 then ring1), split into triangles.
void band(SurfaceMesh& m, int ring0, int ring1, int n) {
  for (int i = 0; i < n; ++i) {
    const int a = ring0 + i, b = ring0 + (i + 1) % n;
    const int c = ring1 + (i + 1) % n, d = ring1 + i;
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  }
}

}  // namespace

ElementShape normalizedElement(const SurfaceMesh& mesh, const char* what) {
  if (mesh.triangles.empty() || mesh.positions.empty())
    throw Error(std::string(what) + " mesh has no triangles");
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double longest = (hi - lo).maxCoeff();
  if (!(longest > 0) || !std::isfinite(longest))
    throw Error(std::string(what) + " mesh has a zero or non-finite bounding box");
  ElementShape out;
  out.mesh.triangles = mesh.triangles;
  out.mesh.positions.reserve(mesh.positions.size());
  const Vec3 centre = 0.5 * (lo + hi);
  for (const Vec3& p : mesh.positions) out.mesh.positions.push_back((p - centre) / longest);
  out.half = 0.5 * (hi - lo) / longest;
  return out;
}

ElementShape builtinStick() {
  constexpr int n = 8;
  constexpr double radius = 0.045;
  SurfaceMesh m;
  for (double x : {-0.5, 0.5})
    for (int i = 0; i < n; ++i) {
      const double a = 2 * pi * (i + 0.5) / n;
      m.positions.emplace_back(x, radius * std::cos(a), radius * std::sin(a));
    }
  m.positions.emplace_back(-0.5, 0, 0);
  m.positions.emplace_back(0.5, 0, 0);
  band(m, 0, n, n);
  fan(m, 2 * n, 0, n, true);       // the end at x = -0.5 faces -x
  fan(m, 2 * n + 1, n, n, false);  // the end at x = +0.5 faces +x
  return normalizedElement(m, "built-in stick");
}

ElementShape builtinLeaf() {
  // Outline y = ±w(x) with w = 0.225 sin(π(x + 0.5)), thickness 0.02 cos(πx) on each side.
  constexpr int n = 12;  // outline points per side, tips excluded
  SurfaceMesh m;
  m.positions.emplace_back(-0.5, 0, 0);  // tip 0
  m.positions.emplace_back(0.5, 0, 0);   // tip 1
  auto x = [&](int i) { return -0.5 + double(i + 1) / (n + 1); };
  auto w = [&](double xi) { return 0.225 * std::sin(pi * (xi + 0.5)); };
  auto h = [&](double xi) { return 0.02 * std::cos(pi * xi); };
  // Per station: edge at +y, top midrib, edge at -y, bottom midrib.
  for (int i = 0; i < n; ++i) {
    const double xi = x(i);
    m.positions.emplace_back(xi, w(xi), 0);
    m.positions.emplace_back(xi, 0, h(xi));
    m.positions.emplace_back(xi, -w(xi), 0);
    m.positions.emplace_back(xi, 0, -h(xi));
  }
  auto id = [&](int i, int k) { return 2 + 4 * i + k; };
  // Ring of 4 around the x axis at each station (counter-clockwise seen from +x): +y, +z, -y,
  // -z. Tubes between stations, cones to the tips.
  for (int i = 0; i + 1 < n; ++i) band(m, id(i, 0), id(i + 1, 0), 4);
  fan(m, 0, id(0, 0), 4, true);
  fan(m, 1, id(n - 1, 0), 4, false);
  return normalizedElement(m, "built-in leaf");
}

}  // namespace tfd::core
