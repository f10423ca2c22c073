#include "core/trace/streamtubes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.h"
#include "core/trace/bishop_frames.h"

namespace tfd::core {
namespace {

void validate(const TubeOptions& o) {
  if (!(std::isfinite(o.radius) && o.radius > 0)) throw Error("streamtubes: radius must be > 0");
  if (o.profile == TubeProfile::Circle && (o.sides < 3 || o.sides > 64))
    throw Error("streamtubes: sides must lie in 3..64");
  if (o.profile == TubeProfile::Ribbon && !(o.ribbonThickness > 0 && o.ribbonThickness <= 1))
    throw Error("streamtubes: ribbon thickness must lie in (0, 1]");
  if (!(o.minWidth >= 0 && o.minWidth <= 1))
    throw Error("streamtubes: the minimum width must lie in [0, 1]");
}

/// Radius per point of every line: constant, or following |λ| of one eigenvalue.
class WidthMap {
 public:
  WidthMap(const Polylines& lines, const TubeOptions& o) : o_(o) {
    if (o.width == TubeWidth::Constant) return;
    index_ = static_cast<int>(o.width) - 1;
    lo_ = std::numeric_limits<double>::infinity();
    hi_ = -lo_;
    for (const Polyline& l : lines.lines) {
      if (l.points.size() < 2) continue;  // not swept
      for (const Vec3& e : l.eigenvalues) {
        lo_ = std::min(lo_, std::abs(e[index_]));
        hi_ = std::max(hi_, std::abs(e[index_]));
      }
    }
  }
  double operator()(const Polyline& line, std::size_t i) const {
    if (index_ < 0 || i >= line.eigenvalues.size()) return o_.radius;
    const double a = std::abs(line.eigenvalues[i][index_]);
    const double t = hi_ > lo_ ? (a - lo_) / (hi_ - lo_) : 1;
    return o_.radius * (o_.minWidth + (1 - o_.minWidth) * t);
  }

 private:
  const TubeOptions& o_;
  int index_ = -1;
  double lo_ = 0, hi_ = 0;
};

/// Writes one closed tube into its ranges of the mesh.
void sweepOne(const Polyline& line, const std::vector<Eigen::Vector2d>& profile,
              const WidthMap& width, SurfaceMesh& mesh, std::size_t v0, std::size_t t0) {
  const std::vector<Frame> frames = bishopFrames(line.points);
  const int m = static_cast<int>(profile.size());
  const std::size_t n = line.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Frame& f = frames[i];
    const double r = width(line, i);
    for (int j = 0; j < m; ++j)
      mesh.positions[v0 + i * m + j] =
          line.points[i] + r * (profile[j].x() * f.normal + profile[j].y() * f.binormal);
  }
  const int startCap = static_cast<int>(v0 + n * m), endCap = startCap + 1;
  mesh.positions[startCap] = line.points.front();
  mesh.positions[endCap] = line.points.back();
  std::size_t t = t0;
  const auto vid = [&](std::size_t i, int j) { return static_cast<int>(v0 + i * m + (j % m)); };
  // Sides: the profile runs counter-clockwise about the tangent, so (a, b, c) faces outward.
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = vid(i, j), b = vid(i, j + 1), c = vid(i + 1, j + 1), d = vid(i + 1, j);
      mesh.triangles[t++] = {a, b, c};
      mesh.triangles[t++] = {a, c, d};
    }
  for (int j = 0; j < m; ++j) {
    mesh.triangles[t++] = {startCap, vid(0, j + 1), vid(0, j)};        // faces −tangent
    mesh.triangles[t++] = {endCap, vid(n - 1, j), vid(n - 1, j + 1)};  // faces +tangent
  }
}

}  // namespace

std::vector<Eigen::Vector2d> tubeProfile(const TubeOptions& o) {
  std::vector<Eigen::Vector2d> p;
  if (o.profile == TubeProfile::Ribbon) {
    const double h = o.ribbonThickness;
    p = {{1, -h}, {1, h}, {-1, h}, {-1, -h}};
    return p;
  }
  for (int j = 0; j < o.sides; ++j) {
    const double a = 2 * std::numbers::pi * j / o.sides;
    p.emplace_back(std::cos(a), std::sin(a));
  }
  return p;
}

SurfaceMesh sweepTubes(const Polylines& lines, const TubeOptions& options,
                       const Progress& progress) {
  validate(options);
  const std::vector<Eigen::Vector2d> profile = tubeProfile(options);
  const std::size_t m = profile.size();
  const WidthMap width(lines, options);
  // Ranges of each tube: vertices n·m + 2, triangles 2·m·(n − 1) + 2·m.
  const std::size_t count = lines.lines.size();
  std::vector<std::size_t> vStart(count + 1, 0), tStart(count + 1, 0);
  for (std::size_t l = 0; l < count; ++l) {
    const std::size_t n = lines.lines[l].points.size();
    const bool swept = n >= 2;
    vStart[l + 1] = vStart[l] + (swept ? n * m + 2 : 0);
    tStart[l + 1] = tStart[l] + (swept ? 2 * m * n : 0);
  }
  if (vStart.back() > std::size_t(std::numeric_limits<int>::max()))
    throw Error("streamtubes: too many vertices for one mesh (" + std::to_string(vStart.back()) +
                "); use fewer sides or fewer lines");
  SurfaceMesh mesh;
  mesh.positions.resize(vStart.back());
  mesh.triangles.resize(tStart.back());
  tbb::parallel_for(std::size_t(0), count, [&](std::size_t l) {
    if (progress.cancelled() || vStart[l + 1] == vStart[l]) return;
    sweepOne(lines.lines[l], profile, width, mesh, vStart[l], tStart[l]);
  });
  progress.throwIfCancelled();
  progress.report(1, "sweeping tubes");
  return mesh;
}

}  // namespace tfd::core
