#include "core/synth/gabor_noise.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "core/error.h"

namespace tfd::core {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTruncation = 0.05;  ///< envelope value at the truncation radius
constexpr double kBlendWidth = 0.5;   ///< confidence at which kernels are fully anisotropic
constexpr double kMaxKernels = 2e7;   ///< about 1 GB of impulses: refuse more

std::uint64_t mix64(std::uint64_t x) {  // splitmix64 finaliser
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

/// splitmix64 generator seeded per cell.
class CellRandom {
 public:
  CellRandom(std::uint64_t seed, int x, int y, int z)
      : state_(mix64(seed ^ mix64(std::uint64_t(std::uint32_t(x)) ^
                                  mix64(std::uint64_t(std::uint32_t(y)) ^
                                        mix64(std::uint64_t(std::uint32_t(z)) + 1))))) {}
  double uniform() {  ///< in [0, 1)
    state_ += 0x9E3779B97F4A7C15ull;
    return double(mix64(state_) >> 11) * 0x1.0p-53;
  }
  int poisson(double mean) {  ///< Knuth's method (mean ≤ 31 here)
    const double limit = std::exp(-mean);
    int k = 0;
    for (double p = uniform(); p > limit; p *= uniform()) ++k;
    return k;
  }
  Vec3 onSphere() {
    const double z = 2 * uniform() - 1, phi = 2 * kPi * uniform();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

 private:
  std::uint64_t state_;
};

/// P(χ²₃ ≤ x): the share of a 3-D Gaussian's mass inside a ball.
double chiSquare3(double x) {
  return std::erf(std::sqrt(x / 2)) - std::sqrt(2 * x / kPi) * std::exp(-x / 2);
}

Vec3 withoutAlong(const Vec3& v, const Vec3& e, double beta) {  // fibres along e
  const Vec3 u = v - beta * v.dot(e) * e;
  const double n = u.norm();
  return n > 1e-12 ? Vec3(u / n) : Vec3(e.unitOrthogonal());
}

Vec3 towards(const Vec3& v, const Vec3& n, double beta) {  // sheets normal to n
  const Vec3 u = v - beta * (v - v.dot(n) * n);
  const double len = u.norm();
  return len > 1e-12 ? Vec3(u / len) : n;
}

/// Nearest boundary vertex by a uniform bucket grid (ring search).
class NearestBoundaryVertex {
 public:
  explicit NearestBoundaryVertex(const TetMesh& mesh) : mesh_(mesh) {
    const auto& ids = mesh.boundaryVertices();
    lo_ = mesh.boundsMin();
    const Vec3 extent = (mesh.boundsMax() - lo_).cwiseMax(1e-12);
    cell_ = std::max(extent.maxCoeff() / 256,
                     std::cbrt(extent.prod() / std::max<std::size_t>(1, ids.size())) * 2);
    for (int a = 0; a < 3; ++a) dims_[a] = std::max(1, int(std::ceil(extent[a] / cell_)));
    start_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    for (int v : ids) ++start_[bucket(clamped(mesh.positions()[v])) + 1];
    for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    ids_.resize(ids.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int v : ids) ids_[fill[bucket(clamped(mesh.positions()[v]))]++] = v;
  }

  int operator()(const Vec3& p) const {
    const auto c = clamped(p);
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    const int maxRing = std::max({dims_[0], dims_[1], dims_[2]});
    for (int ring = 0; ring <= maxRing; ++ring) {
      for (int z = c[2] - ring; z <= c[2] + ring; ++z) {
        for (int y = c[1] - ring; y <= c[1] + ring; ++y) {
          for (int x = c[0] - ring; x <= c[0] + ring; ++x) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != ring)
              continue;
            if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2])
              continue;
            const std::size_t b = bucket({x, y, z});
            for (int k = start_[b]; k < start_[b + 1]; ++k) {
              const double d = (mesh_.positions()[ids_[k]] - p).squaredNorm();
              if (d < bestD || (d == bestD && ids_[k] < best)) bestD = d, best = ids_[k];
            }
          }
        }
      }
      if (best >= 0 && std::sqrt(bestD) <= ring * cell_) break;
    }
    return best;
  }

 private:
  std::array<int, 3> clamped(const Vec3& p) const {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a)
      c[a] = std::clamp(int(std::floor((p[a] - lo_[a]) / cell_)), 0, dims_[a] - 1);
    return c;
  }
  std::size_t bucket(const std::array<int, 3>& c) const {
    return (std::size_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
  }

  const TetMesh& mesh_;
  Vec3 lo_;
  double cell_ = 1;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_, ids_;
};

void requirePositive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0)
    throw Error(std::string("Gabor noise: ") + name + " must be a finite positive number, not " +
                std::to_string(value));
}

}  // namespace

GaborKernelShape gaborKernelShape(const GaborNoiseOptions& o) {
  requirePositive(o.frequency, "frequency");
  requirePositive(o.bandwidth, "bandwidth");
  requirePositive(o.impulsesPerKernel, "impulses per kernel");
  if (o.impulsesPerKernel > 128)
    throw Error("Gabor noise: impulses per kernel must be at most 128, not " +
                std::to_string(o.impulsesPerKernel));
  GaborKernelShape s;
  const double b = std::exp2(o.bandwidth);
  s.a = o.frequency * (b - 1) / (b + 1) * std::sqrt(kPi / std::numbers::ln2);
  s.radius = std::sqrt(-std::log(kTruncation) / kPi) / s.a;
  s.density = o.impulsesPerKernel / (4.0 / 3.0 * kPi * std::pow(s.radius, 3));
  s.variance = s.density * 0.5 * std::pow(2 * s.a * s.a, -1.5) *
               chiSquare3(4 * kPi * s.a * s.a * s.radius * s.radius);
  return s;
}

Vec3 gaborDirection(const Tensor& t, NoiseOrientation mode, const Vec3& v) {
  const EigenDecomposition e = eigenDecompose(t);
  const double l1 = e.values[0], l2 = e.values[1], l3 = e.values[2];
  const double spread = l1 - l3;
  if (!(spread > 1e-12 * (std::abs(l1) + std::abs(l3)))) return v;  // isotropic tensor
  const double cl = (l1 - l2) / spread, cp = (l2 - l3) / spread;
  const auto beta = [](double confidence) { return std::min(1.0, confidence / kBlendWidth); };
  switch (mode) {
    case NoiseOrientation::Major:
      return withoutAlong(v, e.vectors.col(0), beta(cl));
    case NoiseOrientation::Medium:
      return withoutAlong(v, e.vectors.col(1), beta(2 * std::min(cl, cp)));
    case NoiseOrientation::Minor:
      return towards(v, e.vectors.col(2), beta(cp));
    case NoiseOrientation::Auto:
      break;
  }
  return cl >= cp ? withoutAlong(v, e.vectors.col(0), beta(cl - cp))
                  : towards(v, e.vectors.col(2), beta(cp - cl));
}

GaborNoise::GaborNoise(const TensorField& field, const GaborNoiseOptions& options,
                       const Vec3& boxMin, const Vec3& boxMax, const Progress& progress)
    : options_(options), shape_(gaborKernelShape(options)) {
  const double r = shape_.radius;
  for (int a = 0; a < 3; ++a) {
    cellMin_[a] = int(std::floor((boxMin[a] - r) / r));
    cellDims_[a] = int(std::floor((boxMax[a] + r) / r)) - cellMin_[a] + 1;
  }
  const double mean = shape_.density * r * r * r;
  const double cellCount = double(cellDims_[0]) * cellDims_[1] * cellDims_[2];
  if (cellCount * std::max(1.0, mean) > kMaxKernels) {
    std::ostringstream m;
    m << "Gabor noise: frequency " << options.frequency << " needs about "
      << std::llround(cellCount * mean) << " kernels over this volume (at most " << kMaxKernels
      << "): lower the frequency";
    throw Error(m.str());
  }
  const std::size_t cells = std::size_t(cellCount);
  const NearestBoundaryVertex nearest(field.mesh());
  field.mesh().locator();  // build once, outside the parallel loop

  std::vector<std::vector<GaborImpulse>> perCell(cells);
  tbb::parallel_for(std::size_t(0), cells, [&](std::size_t c) {
    if (progress.cancelled()) return;
    const int x = cellMin_[0] + int(c % cellDims_[0]);
    const int y = cellMin_[1] + int(c / cellDims_[0] % cellDims_[1]);
    const int z = cellMin_[2] + int(c / (std::size_t(cellDims_[0]) * cellDims_[1]));
    CellRandom random(options_.seed, x, y, z);
    const int count = random.poisson(mean);
    auto& out = perCell[c];
    out.resize(count);
    for (GaborImpulse& impulse : out) {
      impulse.centre = r * Vec3(x + random.uniform(), y + random.uniform(), z + random.uniform());
      impulse.phase = 2 * kPi * random.uniform();
      const Vec3 v = random.onSphere();
      const std::optional<Tensor> t = field.sample(impulse.centre);
      const Tensor& tensor = t ? *t : field.at(nearest(impulse.centre));
      impulse.omega =
          2 * kPi * options_.frequency * gaborDirection(tensor, options_.orientation, v);
    }
  });
  progress.throwIfCancelled();
  cellStart_.assign(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] = cellStart_[c] + perCell[c].size();
  impulses_.reserve(cellStart_.back());
  for (auto& cell : perCell) impulses_.insert(impulses_.end(), cell.begin(), cell.end());
}

std::array<int, 3> GaborNoise::cellOf(const Vec3& p) const {
  std::array<int, 3> c;
  for (int a = 0; a < 3; ++a) {
    c[a] = std::clamp(int(std::floor(p[a] / shape_.radius)), cellMin_[a],
                      cellMin_[a] + cellDims_[a] - 1);
  }
  return c;
}

double GaborNoise::at(const Vec3& p) const {
  const double r2 = shape_.radius * shape_.radius, pa2 = kPi * shape_.a * shape_.a;
  const auto lo = cellOf(p - Vec3::Constant(shape_.radius));
  const auto hi = cellOf(p + Vec3::Constant(shape_.radius));
  double sum = 0;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) {
        const std::size_t c = cellIndex(x, y, z);
        for (std::size_t i = cellStart_[c]; i < cellStart_[c + 1]; ++i) {
          const GaborImpulse& k = impulses_[i];
          const Vec3 d = p - k.centre;
          const double d2 = d.squaredNorm();
          if (d2 > r2) continue;
          sum += std::exp(-pa2 * d2) * std::cos(k.omega.dot(d) + k.phase);
        }
      }
  return sum;
}

ScalarVolume gaborNoiseVolume(const TensorField& field, const VoxelGrid& grid,
                              const GaborNoiseOptions& options, const Progress& progress,
                              GaborNoiseStats* stats) {
  const GaborKernelShape shape = gaborKernelShape(options);  // bad options fail first
  ScalarVolume volume;
  volume.grid = grid;
  progress.report(0.0, "inside mask");
  volume.mask = insideMask(field.mesh(), grid, progress);
  progress.report(0.1, "impulses");
  const GaborNoise noise(field, options, grid.centre(grid.min[0], grid.min[1], grid.min[2]),
                         grid.centre(grid.max[0], grid.max[1], grid.max[2]), progress);
  progress.report(0.2, "kernels");
  std::size_t evaluations = 0;
  const std::vector<double> raw = noise.sample(grid, volume.mask, progress, &evaluations);
  const double sigma = std::sqrt(shape.variance);
  volume.values.resize(raw.size());
  for (std::size_t v = 0; v < raw.size(); ++v) {
    const double n = raw[v] / sigma;
    double out = n;
    if (options.range == NoiseRange::Positive) out = std::min(1.0, std::max(0.0, n) / 3);
    if (options.range == NoiseRange::Unit) out = std::clamp(0.5 + n / 6, 0.0, 1.0);
    volume.values[v] = volume.mask[v] ? float(out) : 0.0f;
  }
  if (stats) {
    stats->impulses = noise.impulseCount();
    stats->kernelEvaluations = evaluations;
    stats->insideVoxels = volume.activeCount();
    stats->shape = shape;
  }
  progress.report(1.0, "kernels");
  return volume;
}

}  // namespace tfd::core
