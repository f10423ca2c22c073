#include "core/synth/element_synthesis.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "core/point_locator.h"
#include "core/synth/oriented_box.h"
#include "core/synth/spacing_metric.h"

namespace tfd::core {
namespace {

/// SplitMix64: tiny, fast, and the same sequence on every platform (unlike std distributions).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  ///< in [0, 1)
  std::size_t below(std::size_t n) { return std::size_t(uniform() * double(n)); }

 private:
  std::uint64_t state_;
};

/// A sample with everything its neighbours test against.
struct Sample {
  Vec3 position;
  Mat3 metric;
  Mat3 frame;    ///< eigenvectors of the deviator (columns), right-handed
  Vec3 spacing;  ///< h_k along frame column k
  std::optional<ElementKind> kind;
  OrientedBox box;
};

/// Uniform grid of sample ids, searched in a cube around a point.
class SampleGrid {
 public:
  SampleGrid(const Vec3& lo, const Vec3& hi, double cell) : origin_(lo), cell_(cell) {
    const Vec3 extent = hi - lo;
    // Coarser cells rather than more than 2^22 of them.
    while ((extent / cell_).prod() > double(1 << 22)) cell_ *= 1.25;
    for (int i = 0; i < 3; ++i) dims_[i] = std::max(1, int(std::ceil(extent[i] / cell_)));
    cells_.resize(std::size_t(dims_[0]) * dims_[1] * dims_[2]);
  }
  void add(const Vec3& p, int id) { cells_[index(coord(p))].push_back(id); }
  /// Calls hit(id) for the samples in the cells meeting the cube of half-side `radius`
  /// around p, until it returns true.
  template <class F>
  bool anyNear(const Vec3& p, double radius, F&& hit) const {
    const auto lo = coord(p - Vec3::Constant(radius)), hi = coord(p + Vec3::Constant(radius));
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          for (int id : cells_[index({i, j, k})])
            if (hit(id)) return true;
    return false;
  }

 private:
  std::array<int, 3> coord(const Vec3& p) const {
    std::array<int, 3> c;
    for (int i = 0; i < 3; ++i)
      c[i] = std::clamp(int(std::floor((p[i] - origin_[i]) / cell_)), 0, dims_[i] - 1);
    return c;
  }
  std::size_t index(const std::array<int, 3>& c) const {
    return std::size_t(c[0]) + std::size_t(dims_[0]) * (c[1] + std::size_t(dims_[1]) * c[2]);
  }
  Vec3 origin_;
  double cell_;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

class Sampler {
 public:
  Sampler(const TensorField& field, const ElementShapes& shapes, const ElementSynthesisOptions& o,
          double size)
      : field_(field),
        shapes_(shapes),
        o_(o),
        size_(size),
        random_(o.seed),
        metric_(size / o.density, o.anisotropy, referenceNorm(field)),
        grid_(field.mesh().boundsMin(), field.mesh().boundsMax(), cellSize()) {
    const auto& volumes = field.mesh().tetVolumes();
    cumulative_.resize(volumes.size());
    double sum = 0;
    for (std::size_t t = 0; t < volumes.size(); ++t) cumulative_[t] = sum += volumes[t];
  }

  void run(ElementPlacement& out, const Progress& progress);

 private:
  static double referenceNorm(const TensorField& field) {
    double sum = 0;  // sequential: the same bits on any thread count
    for (const Tensor& t : field.values()) sum += t.deviator().norm() * t.deviator().norm();
    return std::sqrt(sum / double(std::max<std::size_t>(1, field.values().size())));
  }
  double cellSize() const { return std::max({metric_.spacing(), 2 * maxElementRadius(), 1e-12}); }
  double maxElementRadius() const {
    double radius = 0;
    for (ElementKind k : {ElementKind::Line, ElementKind::Box})
      radius = std::max(radius, size_ * shapes_.of(k).half.norm());
    return radius;
  }
  std::optional<Sample> evaluate(const Vec3& p) const;
  Vec3 randomPointInVolume();
  Vec3 randomAround(const Sample& s);
  /// True when q is accepted (and then appended to the samples).
  bool tryAccept(Sample q, ElementPlacement& out);

  const TensorField& field_;
  const ElementShapes& shapes_;
  const ElementSynthesisOptions& o_;
  double size_;
  Random random_;
  SpacingMetric metric_;
  SampleGrid grid_;
  std::vector<double> cumulative_;
  std::vector<Sample> samples_;
};

std::optional<Sample> Sampler::evaluate(const Vec3& p) const {
  const auto location = field_.mesh().locator().locate(p);
  if (!location) return {};
  const Tensor a = field_.interpolate(location->tet, location->barycentric).deviator();
  const EigenDecomposition e = eigenDecompose(a);
  Sample s;
  s.position = p;
  s.frame = e.vectors;
  s.spacing = metric_.spacings(e.values);
  s.metric = metric_.metric(e);
  const double norm = a.norm();
  if (norm > 1e-12 * metric_.referenceNorm() && std::abs(e.values[1]) > 1e-12 * norm) {
    s.kind = e.values[1] < 0 ? ElementKind::Line : ElementKind::Box;
    s.box.centre = p;
    s.box.axes = e.vectors;
    s.box.half = size_ * shapes_.of(*s.kind).half;
  }
  return s;
}

Vec3 Sampler::randomPointInVolume() {
  const double u = random_.uniform() * cumulative_.back();
  const std::size_t t = std::min<std::size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin(),
      cumulative_.size() - 1);
  // Uniform in the tet: normalised exponentials are uniform barycentric coordinates.
  double b[4], sum = 0;
  for (double& bi : b) sum += bi = -std::log(1 - random_.uniform());
  const auto& tet = field_.mesh().tets()[t];
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < 4; ++i) p += b[i] / sum * field_.mesh().positions()[tet[i]];
  return p;
}

Vec3 Sampler::randomAround(const Sample& s) {
  // u uniform in the shell 1 ≤ |u| ≤ 2 (rejection from the cube), mapped by the sample's
  // ellipsoid: metric distance |u| from s.
  Vec3 u;
  do {
    for (int i = 0; i < 3; ++i) u[i] = 4 * random_.uniform() - 2;
  } while (u.squaredNorm() < 1 || u.squaredNorm() > 4);
  return s.position + s.frame * s.spacing.cwiseProduct(u);
}

bool Sampler::tryAccept(Sample q, ElementPlacement& out) {
  // M̄ ⪰ M(q)/2, so a conflicting sample lies within √2 h_max(q) of q.
  const double conflictRadius = std::sqrt(2.0) * q.spacing.maxCoeff();
  const bool conflict = grid_.anyNear(q.position, conflictRadius, [&](int id) {
    const Sample& p = samples_[id];
    const Vec3 d = q.position - p.position;
    return d.dot(0.5 * (p.metric + q.metric) * d) < 1;
  });
  if (conflict) return false;
  if (o_.rejectOverlaps && q.kind) {
    const double reach = q.box.boundingRadius() + maxElementRadius();
    const bool collides = grid_.anyNear(q.position, reach, [&](int id) {
      const Sample& p = samples_[id];
      return p.kind && boxesOverlap(p.box, q.box);
    });
    if (collides) {
      ++out.report.overlapRejected;
      return false;
    }
  }
  if (q.kind) {
    InstancePoint ip;
    ip.position = q.position;
    const Eigen::Quaterniond rotation(q.frame);
    ip.orient = {rotation.w(), rotation.x(), rotation.y(), rotation.z()};
    ip.orient.normalize();
    ip.scale = Vec3::Constant(size_);
    ip.kind = *q.kind;
    out.points.points.push_back(ip);
    ++(ip.kind == ElementKind::Line ? out.report.lines : out.report.boxes);
  } else {
    ++out.report.neutral;
  }
  grid_.add(q.position, int(samples_.size()));
  samples_.push_back(std::move(q));
  ++out.report.samples;
  return true;
}

void Sampler::run(ElementPlacement& out, const Progress& progress) {
  constexpr int kSeedDarts = 64;
  std::vector<int> active;
  const std::size_t maxElements = std::size_t(std::max(0, o_.maxElements));
  std::size_t lastReport = 0;
  while (out.points.points.size() < maxElements) {
    if (active.empty()) {  // (re)start from a random point of the volume
      bool seeded = false;
      for (int dart = 0; dart < kSeedDarts && !seeded; ++dart) {
        if (auto s = evaluate(randomPointInVolume())) seeded = tryAccept(std::move(*s), out);
      }
      if (!seeded) break;
      active.push_back(int(samples_.size()) - 1);
      continue;
    }
    const std::size_t pick = random_.below(active.size());
    const Sample centre = samples_[active[pick]];
    bool found = false;
    for (int k = 0; k < o_.attempts && !found; ++k) {
      if (auto s = evaluate(randomAround(centre))) found = tryAccept(std::move(*s), out);
    }
    if (found) {
      active.push_back(int(samples_.size()) - 1);
    } else {
      active[pick] = active.back();
      active.pop_back();
    }
    if (samples_.size() >= lastReport + 1024) {
      lastReport = samples_.size();
      progress.throwIfCancelled();
      progress.report(double(out.points.points.size()) / double(maxElements), "placing elements");
    }
  }
  out.report.hitMaxElements = out.points.points.size() >= maxElements;
}

}  // namespace

std::string ElementSynthesisReport::summary() const {
  std::string s = std::to_string(lines + boxes) + " elements (" + std::to_string(lines) +
                  " sticks, " + std::to_string(boxes) + " leaves) of size " + std::to_string(size) +
                  " at " + std::to_string(samples) + " samples";
  if (overlapRejected)
    s += ", " + std::to_string(overlapRejected) + " colliding candidates dropped";
  if (neutral) s += ", " + std::to_string(neutral) + " samples neutral (no element)";
  if (hitMaxElements) s += ", stopped at the element limit";
  return s;
}

ElementPlacement placeElements(const TensorField& field, const ElementShapes& shapes,
                               const ElementSynthesisOptions& options, const Progress& progress) {
  double size = options.size;
  if (size == 0) size = (field.mesh().boundsMax() - field.mesh().boundsMin()).norm() / 25;
  if (!(size > 0) || !std::isfinite(size))
    throw Error("element size must be positive, not " + std::to_string(options.size));
  if (!(options.density > 0) || !std::isfinite(options.density))
    throw Error("element density must be positive, not " + std::to_string(options.density));
  if (!(options.anisotropy >= 0) || !std::isfinite(options.anisotropy))
    throw Error("anisotropy must be zero or positive, not " + std::to_string(options.anisotropy));
  if (options.attempts < 1)
    throw Error("attempts must be at least 1, not " + std::to_string(options.attempts));
  ElementPlacement out;
  out.report.size = size;
  Sampler sampler(field, shapes, options, size);
  sampler.run(out, progress);
  return out;
}

Mat3 rotationOf(const Eigen::Vector4d& orient) {
  return Eigen::Quaterniond(orient[0], orient[1], orient[2], orient[3])
      .normalized()
      .toRotationMatrix();
}

SurfaceMesh instanceElements(const InstancePoints& points, const ElementShapes& shapes) {
  const auto& all = points.points;
  std::vector<std::size_t> vertexStart(all.size() + 1, 0), triangleStart(all.size() + 1, 0);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const SurfaceMesh& m = shapes.of(all[i].kind).mesh;
    vertexStart[i + 1] = vertexStart[i] + m.positions.size();
    triangleStart[i + 1] = triangleStart[i] + m.triangles.size();
  }
  SurfaceMesh out;
  out.positions.resize(vertexStart.back());
  out.triangles.resize(triangleStart.back());
  tbb::parallel_for(std::size_t(0), all.size(), [&](std::size_t i) {
    const InstancePoint& ip = all[i];
    const SurfaceMesh& m = shapes.of(ip.kind).mesh;
    const Mat3 r = rotationOf(ip.orient);
    for (std::size_t v = 0; v < m.positions.size(); ++v)
      out.positions[vertexStart[i] + v] = ip.position + r * ip.scale.cwiseProduct(m.positions[v]);
    const int base = int(vertexStart[i]);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& tri = m.triangles[t];
      out.triangles[triangleStart[i] + t] = {base + tri[0], base + tri[1], base + tri[2]};
    }
  });
  return out;
}

}  // namespace tfd::core
