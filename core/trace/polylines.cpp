#include "core/trace/polylines.h"

#include <cstdio>

namespace tfd::core {

const char* toString(EigenFamily family) {
  switch (family) {
    case EigenFamily::Major:
      return "major";
    case EigenFamily::Medium:
      return "medium";
    case EigenFamily::Minor:
      return "minor";
  }
  return "?";
}

const char* toString(LineStop stop) {
  switch (stop) {
    case LineStop::Degenerate:
      return "degenerate";
    case LineStop::Boundary:
      return "boundary";
    case LineStop::SharpTurn:
      return "sharp turn";
    case LineStop::MaxLength:
      return "max length";
    case LineStop::TooClose:
      return "too close";
  }
  return "?";
}

double Polyline::length() const {
  double s = 0;
  for (std::size_t i = 1; i < points.size(); ++i) s += (points[i] - points[i - 1]).norm();
  return s;
}

std::size_t Polylines::pointCount() const {
  std::size_t n = 0;
  for (const Polyline& l : lines) n += l.points.size();
  return n;
}

double Polylines::totalLength() const {
  double s = 0;
  for (const Polyline& l : lines) s += l.length();
  return s;
}

std::size_t Polylines::byteSize() const {
  return pointCount() * 2 * sizeof(Vec3) + lines.size() * sizeof(Polyline);
}

std::string Polylines::summary() const {
  char length[32];
  std::snprintf(length, sizeof length, "%.4g", totalLength());
  std::string s = std::to_string(lines.size()) + " " + toString(family) + " lines, " +
                  std::to_string(pointCount()) + " points, length " + length;
  std::array<std::size_t, 5> ends{};
  for (const Polyline& l : lines)
    for (LineStop stop : l.stops) ++ends[static_cast<std::size_t>(stop)];
  std::string list;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    if (ends[k] == 0) continue;
    list += (list.empty() ? "" : ", ") + std::to_string(ends[k]) + " " +
            toString(static_cast<LineStop>(k));
  }
  if (!list.empty()) s += "; ends: " + list;
  return s;
}

}  // namespace tfd::core
