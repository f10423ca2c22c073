#include "core/trace/hyperstreamlines.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <string>

#include "core/error.h"
#include "core/trace/bishop_frames.h"
#include "core/trace/eigen_sampler.h"
#include "core/trace/line_tracer.h"
#include "core/trace/point_grid.h"

namespace tfd::core {
namespace {

void check(bool ok, const std::string& what) {
  if (!ok) throw Error("hyperstreamlines: " + what);
}

void validate(const TetMesh& mesh, const HyperstreamlineOptions& o) {
  check(std::isfinite(o.separation) && o.separation > 0, "separation must be positive");
  check(o.testRatio > 0 && o.testRatio <= 1, "the test ratio must lie in (0, 1]");
  check(std::isfinite(o.step) && o.step >= 0, "the step must be 0 (automatic) or positive");
  check(o.maxTurnDegrees > 0 && o.maxTurnDegrees <= 90, "the maximum turn must lie in (0, 90]");
  check(std::isfinite(o.minGap) && o.minGap >= 0, "the minimum eigen-gap must be >= 0");
  check(std::isfinite(o.maxLength) && o.maxLength >= 0, "the maximum length must be >= 0");
  check(std::isfinite(o.minLength) && o.minLength >= 0, "the minimum length must be >= 0");
  const double extent = (mesh.boundsMax() - mesh.boundsMin()).maxCoeff();
  check(extent / o.separation <= 4096, "separation " + std::to_string(o.separation) +
                                           " is too small for a mesh " + std::to_string(extent) +
                                           " wide (at most 4096 lines across)");
  for (std::size_t i = 0; i < o.seeds.size(); ++i)
    check(o.seeds[i].allFinite(), "seed " + std::to_string(i) + " is not a finite point");
}

/// Jobard-Lefer placement: state shared by the seeds of one call.
class Placer {
 public:
  Placer(const TensorField& field, const HyperstreamlineOptions& o)
      : o_(o), sampler_(field, o.family), dTest_(o.separation * o.testRatio), grid_(o.separation) {
    trace_.step = hyperstreamlineStep(field, o);
    trace_.minGap = o.minGap;
    trace_.maxTurnDegrees = o.maxTurnDegrees;
    if (o.maxLength > 0) trace_.maxHalfLength = 0.5 * o.maxLength;
    window_ = 2 * dTest_ + trace_.step;
    out_.family = o.family;
  }

  /// Traces a line from `seed` when it lies `clearance` away from every line and on a
  /// non-degenerate point; true when the line was kept.
  bool trySeed(const Vec3& seed, double clearance) {
    if (grid_.anyWithin(seed, clearance)) return false;
    const auto s = sampler_.sample(seed);
    if (!s || s->gap < o_.minGap) return false;
    const int id = static_cast<int>(out_.lines.size());
    grid_.insert(seed, id, 0);
    // Each accepted point joins the grid at once, so a line cannot come back onto itself.
    const ProximityTest tooClose = [&](const Vec3& p, double arc) {
      if (grid_.anyWithin(p, dTest_, id, arc, window_)) return true;
      grid_.insert(p, id, arc);
      return false;
    };
    const HalfLine ahead = traceHalfLine(sampler_, trace_, seed, *s, +1, tooClose);
    const HalfLine behind = traceHalfLine(sampler_, trace_, seed, *s, -1, tooClose);
    Polyline line;
    line.points.assign(behind.points.rbegin(), behind.points.rend());
    line.eigenvalues.assign(behind.eigenvalues.rbegin(), behind.eigenvalues.rend());
    line.points.push_back(seed);
    line.eigenvalues.push_back(s->eigenvalues);
    line.points.insert(line.points.end(), ahead.points.begin(), ahead.points.end());
    line.eigenvalues.insert(line.eigenvalues.end(), ahead.eigenvalues.begin(),
                            ahead.eigenvalues.end());
    line.stops = {behind.stop, ahead.stop};
    if (line.points.size() < 2 || line.length() < o_.minLength) {
      grid_.rollback();
      return false;
    }
    grid_.commit();
    if (o_.automaticSeeds) addCandidates(line);
    out_.lines.push_back(std::move(line));
    return true;
  }

  /// Seeds `separation` away from the line, every half separation along it, in six
  /// directions around it.
  void addCandidates(const Polyline& line) {
    const auto& p = line.points;
    double since = o_.separation;  // a candidate ring at the first point
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i > 0) since += (p[i] - p[i - 1]).norm();
      if (since < 0.5 * o_.separation) continue;
      since = 0;
      const Vec3 t = (p[std::min(i + 1, p.size() - 1)] - p[i > 0 ? i - 1 : 0]).normalized();
      const Vec3 u = anyPerpendicular(t), v = t.cross(u);
      for (int k = 0; k < 6; ++k) {
        const double a = k * std::numbers::pi / 3;
        queue_.push_back(p[i] + o_.separation * (std::cos(a) * u + std::sin(a) * v));
      }
    }
  }

  void run(const TetMesh& mesh, const Progress& progress) {
    for (const Vec3& seed : o_.seeds) {
      progress.throwIfCancelled();
      trySeed(seed, dTest_);
      drainQueue(progress);
    }
    if (!o_.automaticSeeds) return;
    const std::vector<Vec3> fallback = fallbackSeeds(mesh);
    for (std::size_t i = 0; i < fallback.size(); ++i) {
      progress.throwIfCancelled();
      if (trySeed(fallback[i], o_.separation)) {
        drainQueue(progress);
        progress.report(double(i + 1) / double(fallback.size()), "tracing lines");
      }
    }
  }

  Polylines take() { return std::move(out_); }

 private:
  void drainQueue(const Progress& progress) {
    while (!queue_.empty()) {
      progress.throwIfCancelled();
      const Vec3 seed = queue_.front();
      queue_.pop_front();
      trySeed(seed, o_.separation);
    }
  }

  /// A lattice over the bounding box (spacing the separation, at most 64 per axis), nearest
  /// the box centre first: seeds for parts the lines have not reached.
  std::vector<Vec3> fallbackSeeds(const TetMesh& mesh) const {
    const Vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax(), centre = 0.5 * (lo + hi);
    const double g = std::max(o_.separation, (hi - lo).maxCoeff() / 64);
    std::array<int, 3> n;
    for (int a = 0; a < 3; ++a) n[a] = std::max(1, int(std::floor((hi[a] - lo[a]) / g)) + 1);
    std::vector<std::pair<double, Vec3>> keyed;
    keyed.reserve(std::size_t(n[0]) * n[1] * n[2]);
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const Vec3 p =
              centre + g * Vec3(i - 0.5 * (n[0] - 1), j - 0.5 * (n[1] - 1), k - 0.5 * (n[2] - 1));
          keyed.push_back({(p - centre).squaredNorm(), p});
        }
    // Stable: equal distances keep the lattice order.
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Vec3> seeds;
    seeds.reserve(keyed.size());
    for (const auto& [d, p] : keyed) seeds.push_back(p);
    return seeds;
  }

  const HyperstreamlineOptions& o_;
  EigenSampler sampler_;
  TraceOptions trace_;
  double dTest_, window_ = 0;
  PointGrid grid_;
  std::deque<Vec3> queue_;
  Polylines out_;
};

}  // namespace

double hyperstreamlineStep(const TensorField& field, const HyperstreamlineOptions& o) {
  if (o.step > 0) return o.step;
  return 0.5 * std::min(o.separation * o.testRatio, field.mesh().meanEdgeLength());
}

Polylines traceHyperstreamlines(const TensorField& field, const HyperstreamlineOptions& options,
                                const Progress& progress) {
  validate(field.mesh(), options);
  Placer placer(field, options);
  placer.run(field.mesh(), progress);
  progress.report(1, "tracing lines");
  return placer.take();
}

}  // namespace tfd::core
