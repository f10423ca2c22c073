#include "core/trace/bishop_frames.h"

#include <cmath>

namespace tfd::core {

Vec3 anyPerpendicular(const Vec3& t) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(t[a]) < std::abs(t[axis])) axis = a;
  return t.cross(Vec3::Unit(axis)).normalized();
}

std::vector<Vec3> polylineTangents(const std::vector<Vec3>& points) {
  const std::size_t n = points.size();
  std::vector<Vec3> chords(n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Vec3 e = points[i + 1] - points[i];
    const double len = e.norm();
    chords[i] = len > 0 ? Vec3(e / len) : Vec3::Zero();
  }
  std::vector<Vec3> tangents(n, Vec3::UnitX());
  Vec3 last = Vec3::UnitX();
  // First non-zero chord, for leading duplicates.
  for (const Vec3& c : chords)
    if (!c.isZero()) {
      last = c;
      break;
    }
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 t = Vec3::Zero();
    if (i > 0) t += chords[i - 1];
    if (i + 1 < n) t += chords[i];
    const double len = t.norm();
    // A cusp (chords cancel) or duplicates keep the previous tangent.
    if (len > 1e-12) last = t / len;
    tangents[i] = last;
  }
  return tangents;
}

std::vector<Frame> bishopFrames(const std::vector<Vec3>& points) {
  const std::vector<Vec3> t = polylineTangents(points);
  std::vector<Frame> frames(points.size());
  if (points.empty()) return frames;
  Vec3 r = anyPerpendicular(t[0]);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) {
      const Vec3 v1 = points[i] - points[i - 1];
      const double c1 = v1.squaredNorm();
      if (c1 > 0) {
        const Vec3 rL = r - (2 / c1) * v1.dot(r) * v1;
        const Vec3 tL = t[i - 1] - (2 / c1) * v1.dot(t[i - 1]) * v1;
        const Vec3 v2 = t[i] - tL;
        const double c2 = v2.squaredNorm();
        r = c2 > 0 ? Vec3(rL - (2 / c2) * v2.dot(rL) * v2) : rL;
      }
      // Remove rounding drift: r stays a unit perpendicular of t.
      r -= r.dot(t[i]) * t[i];
      const double len = r.norm();
      r = len > 1e-12 ? Vec3(r / len) : anyPerpendicular(t[i]);
    }
    frames[i] = {t[i], r, t[i].cross(r)};
  }
  return frames;
}

}  // namespace tfd::core
