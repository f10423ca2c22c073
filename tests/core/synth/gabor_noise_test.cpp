// Gabor noise oriented by a tensor field: statistics against the kernel formulas (mean 0,
// variance from Campbell's theorem), the correlation along and across the structure against
// its closed form (the Fourier pair of the spectrum: fibres have their spectrum on a ring
// perpendicular to e1, sheets on the axis e3), the lattice splat against direct evaluation,
// and the same bytes for any thread count.
#include "core/synth/gabor_noise.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "tests/support/carved_ball.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

/// e1 = (1, 1, 0)/√2, e2 = (−1, 1, 0)/√2, e3 = z.
Mat3 diagonalFrame() {
  Mat3 r;
  r.col(0) = Vec3(1, 1, 0).normalized();
  r.col(1) = Vec3(-1, 1, 0).normalized();
  r.col(2) = Vec3(0, 0, 1);
  return r;
}

Tensor inFrame(double l1, double l2, double l3) {
  const Mat3 r = diagonalFrame();
  return Tensor::fromMatrix(r * Vec3(l1, l2, l3).asDiagonal() * r.transpose());
}

TensorField constantField(const Tensor& t) {
  auto mesh = makeBoxMesh(3, 3, 3, Vec3::Zero(), Vec3::Ones());
  const std::size_t n = mesh->vertexCount();
  return TensorField(std::move(mesh), std::vector<Tensor>(n, t));
}

/// Voxel centres at multiples of 1/128 strictly inside [0, 1]³.
VoxelGrid unitGrid(int per = 128) {
  VoxelGrid g;
  g.voxelSize = 1.0 / per;
  g.min = {1, 1, 1};
  g.max = {per - 1, per - 1, per - 1};
  return g;
}

GaborNoiseOptions options(NoiseOrientation mode, double frequency = 32) {
  GaborNoiseOptions o;
  o.frequency = frequency;
  o.bandwidth = 1;
  o.impulsesPerKernel = 16;
  o.seed = 7;
  o.orientation = mode;
  o.range = NoiseRange::Signed;
  return o;
}

struct Moments {
  double mean = 0, variance = 0;
};

Moments moments(const ScalarVolume& v) {
  double s = 0, s2 = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < v.values.size(); ++i) {
    if (!v.mask[i]) continue;
    s += v.values[i];
    s2 += double(v.values[i]) * v.values[i];
    ++n;
  }
  return {s / n, s2 / n - (s / n) * (s / n)};
}

/// Mean of N(x) N(x + lag) over the grid, divided by the mean of N².
double correlation(const ScalarVolume& v, int di, int dj, int dk) {
  const VoxelGrid& g = v.grid;
  double sum = 0, sum2 = 0;
  for (int k = g.min[2]; k <= g.max[2]; ++k)
    for (int j = g.min[1]; j <= g.max[1]; ++j)
      for (int i = g.min[0]; i <= g.max[0]; ++i) {
        const double a = v.at(i, j, k);
        sum2 += a * a;
        const int i2 = i + di, j2 = j + dj, k2 = k + dk;
        if (i2 < g.min[0] || i2 > g.max[0] || j2 < g.min[1] || j2 > g.max[1] || k2 < g.min[2] ||
            k2 > g.max[2])
          continue;
        sum += a * v.at(i2, j2, k2);
      }
  return sum / sum2;  // the lag's missing pairs are a few percent of the box: see the tolerance
}

TEST(GaborNoise, KernelShapeFollowsTheFormulas) {
  GaborNoiseOptions o = options(NoiseOrientation::Auto, 10);
  o.bandwidth = 2;
  const GaborKernelShape s = gaborKernelShape(o);
  EXPECT_NEAR(s.a, 10 * 3.0 / 5.0 * std::sqrt(kPi / std::log(2.0)), 1e-12);
  EXPECT_NEAR(std::exp(-kPi * s.a * s.a * s.radius * s.radius), 0.05, 1e-12);
  EXPECT_NEAR(s.density * 4.0 / 3.0 * kPi * std::pow(s.radius, 3), 16, 1e-9);
  // Variance by quadrature of λ ∫_{|x|<r} ½ exp(−2π a² |x|²) dx (radial, midpoint rule).
  double integral = 0;
  const int steps = 200000;
  for (int i = 0; i < steps; ++i) {
    const double rho = (i + 0.5) * s.radius / steps;
    integral += 4 * kPi * rho * rho * 0.5 * std::exp(-2 * kPi * s.a * s.a * rho * rho);
  }
  integral *= s.radius / steps;
  EXPECT_NEAR(s.variance / (s.density * integral), 1.0, 1e-6);
}

TEST(GaborNoise, BadOptionsNameTheOption) {
  GaborNoiseOptions o = options(NoiseOrientation::Auto);
  o.frequency = 0;
  EXPECT_THROW(
      try { gaborKernelShape(o); } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("frequency"), std::string::npos);
        throw;
      },
      Error);
  o = options(NoiseOrientation::Auto);
  o.bandwidth = std::nan("");
  EXPECT_THROW(gaborKernelShape(o), Error);
  o = options(NoiseOrientation::Auto);
  o.impulsesPerKernel = 500;
  EXPECT_THROW(gaborKernelShape(o), Error);
  // Far too many kernels for the box: refused before anything is allocated, naming frequency.
  o = options(NoiseOrientation::Auto, 2000);
  try {
    GaborNoise(constantField(Tensor{}), o, Vec3::Zero(), Vec3::Ones());
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("frequency 2000"), std::string::npos) << e.what();
  }
}

TEST(GaborNoise, DirectionsFollowTheTensor) {
  const Mat3 r = diagonalFrame();
  const Vec3 e1 = r.col(0), e3 = r.col(2);
  const Vec3 vs[] = {Vec3(0.3, -0.8, 0.52).normalized(), Vec3(0.9, 0.1, -0.42).normalized()};
  for (const Vec3& v : vs) {
    // Linear: fibres along e1 in auto and major; planar: sheets normal to e3 in auto and minor.
    for (auto mode : {NoiseOrientation::Auto, NoiseOrientation::Major}) {
      const Vec3 u = gaborDirection(inFrame(1, -0.5, -0.5), mode, v);
      EXPECT_NEAR(u.norm(), 1, 1e-12);
      EXPECT_NEAR(u.dot(e1), 0, 1e-12);
    }
    for (auto mode : {NoiseOrientation::Auto, NoiseOrientation::Minor}) {
      const Vec3 u = gaborDirection(inFrame(0.5, 0.5, -1), mode, v);
      EXPECT_NEAR(std::abs(u.dot(e3)), 1, 1e-12);
    }
    // Medium on a tensor with distinct, evenly spaced eigenvalues: fibres along e2.
    EXPECT_NEAR(gaborDirection(inFrame(1, 0, -1), NoiseOrientation::Medium, v).dot(r.col(1)), 0,
                1e-12);
    // Where the structure is undefined the kernel is isotropic: u = v.
    EXPECT_NEAR((gaborDirection(Tensor{}, NoiseOrientation::Auto, v) - v).norm(), 0, 1e-15);
    EXPECT_NEAR((gaborDirection(inFrame(1, 0, -1), NoiseOrientation::Auto, v) - v).norm(), 0, 1e-12)
        << "neutral tensor, linear-planar transition";
    EXPECT_NEAR((gaborDirection(inFrame(0.5, 0.5, -1), NoiseOrientation::Major, v) - v).norm(), 0,
                1e-12)
        << "e1 is undefined on a planar-degenerate tensor";
    // Half-way: the component along e1 is halved (β = ½ at c_l = ¼).
    const Vec3 u = gaborDirection(inFrame(1, 0.5, -1), NoiseOrientation::Major, v);
    const Vec3 expected = (v - 0.5 * v.dot(e1) * e1).normalized();
    EXPECT_NEAR((u - expected).norm(), 0, 1e-12);
  }
}

TEST(GaborNoise, MeanIsZeroAndVarianceMatchesTheKernelFormula) {
  const struct {
    Tensor t;
    NoiseOrientation mode;
  } cases[] = {{Tensor{}, NoiseOrientation::Auto},
               {inFrame(1, -0.5, -0.5), NoiseOrientation::Auto},
               {inFrame(0.5, 0.5, -1), NoiseOrientation::Auto},
               {inFrame(1, 0.2, -1.2), NoiseOrientation::Medium}};
  for (const auto& c : cases) {
    const TensorField field = constantField(c.t);
    GaborNoiseStats stats;
    const ScalarVolume v = gaborNoiseVolume(field, unitGrid(), options(c.mode), {}, &stats);
    EXPECT_EQ(stats.insideVoxels, unitGrid().count());
    const Moments m = moments(v);  // Signed: N / σ with σ² from the formula
    EXPECT_NEAR(m.mean, 0, 0.03);
    EXPECT_NEAR(m.variance, 1, 0.05);
  }
}

TEST(GaborNoise, FibresCorrelateAlongTheMajorEigenvectorAndSheetsAcrossTheMinor) {
  // With random phases the autocorrelation of the noise is, for a lag d,
  //   ρ(d) = E_f[cos 2π f·d] · L(|d|) / L(0),  L(s) = ∫ over the lens B(0, r) ∩ B(s e, r) of
  //   exp(−π a² (|x|² + |x − s e|²)) dx  (the truncated kernels' overlap),
  // with f uniform on the circle of radius F ⊥ e1 (fibres): E = 1 along e1, J0(2πF|d|) across;
  // f = ±F e3 (sheets): E = cos(2πF|d|) along e3, 1 across.
  const GaborNoiseOptions o = options(NoiseOrientation::Auto);
  const GaborKernelShape shape = gaborKernelShape(o);
  const double a = shape.a, r = shape.radius, h = unitGrid().voxelSize, F = o.frequency;
  const auto lens = [&](double s) {  // radial part in closed form, axial by the midpoint rule
    const double lo = s - r, hi = r, A = kPi * a * a;
    const int steps = 20000;
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
      const double t = lo + (i + 0.5) * (hi - lo) / steps;
      const double R2 = std::min(r * r - t * t, r * r - (t - s) * (t - s));
      if (R2 <= 0) continue;
      sum += (1 - std::exp(-2 * A * R2)) / (2 * a * a) * std::exp(-A * (t * t + (t - s) * (t - s)));
    }
    return sum * (hi - lo) / steps;
  };
  const auto envelope = [&](double d) { return lens(d) / lens(0); };
  const double diag = std::sqrt(2.0) * h;
  {
    const ScalarVolume v = gaborNoiseVolume(constantField(inFrame(1, -0.5, -0.5)), unitGrid(), o);
    for (int m : {1, 2}) {
      EXPECT_NEAR(correlation(v, m, m, 0), envelope(m * diag), 0.03) << "along e1, lag " << m;
      EXPECT_NEAR(correlation(v, -m, m, 0),
                  envelope(m * diag) * std::cyl_bessel_j(0.0, 2 * kPi * F * m * diag), 0.03)
          << "along e2, lag " << m;
      EXPECT_NEAR(correlation(v, 0, 0, m),
                  envelope(m * h) * std::cyl_bessel_j(0.0, 2 * kPi * F * m * h), 0.03)
          << "along e3, lag " << m;
    }
  }
  {
    const ScalarVolume v = gaborNoiseVolume(constantField(inFrame(0.5, 0.5, -1)), unitGrid(), o);
    for (int m : {1, 2}) {
      EXPECT_NEAR(correlation(v, m, m, 0), envelope(m * diag), 0.03) << "along e1, lag " << m;
      EXPECT_NEAR(correlation(v, -m, m, 0), envelope(m * diag), 0.03) << "along e2, lag " << m;
      EXPECT_NEAR(correlation(v, 0, 0, m), envelope(m * h) * std::cos(2 * kPi * F * m * h), 0.03)
          << "along e3, lag " << m;
    }
  }
}

/// A field whose type changes across the ball: linear near x < 0, planar near x > 0.
TensorField designedField() {
  auto mesh = test::carvedBall(12, Vec3::Zero(), 1.0);
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    values.push_back(Tensor{1.0 - p.x(), 0.2 * p.y(), -1.0 + p.x(), 0.4 * p.z(), 0.3 * p.x(),
                            0.5 * p.y() * p.z()}
                         .deviator());
  }
  return TensorField(std::move(mesh), std::move(values));
}

VoxelGrid ballGrid() {
  VoxelGrid g;
  g.voxelSize = 1.0 / 40;
  g.min = {-41, -41, -41};
  g.max = {41, 41, 41};
  return g;
}

TEST(GaborNoise, SameBytesForOneAndTwoThreads) {
  const TensorField field = designedField();
  GaborNoiseOptions o = options(NoiseOrientation::Auto, 6);
  o.range = NoiseRange::Positive;
  std::vector<float> first;
  for (int threads : {1, 2}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    const ScalarVolume v = gaborNoiseVolume(field, ballGrid(), o);
    if (first.empty()) {
      first = v.values;
      continue;
    }
    ASSERT_EQ(v.values.size(), first.size());
    EXPECT_EQ(std::memcmp(v.values.data(), first.data(), first.size() * sizeof(float)), 0);
  }
  o.seed = 8;
  const ScalarVolume other = gaborNoiseVolume(field, ballGrid(), o);
  EXPECT_NE(other.values, first) << "the seed changes the noise";
}

TEST(GaborNoise, LatticeSplatEqualsDirectEvaluationAndDoesNotDependOnTheGrid) {
  const TensorField field = designedField();
  const GaborNoiseOptions o = options(NoiseOrientation::Auto, 6);
  const VoxelGrid grid = ballGrid();
  const std::vector<std::uint8_t> mask = insideMask(field.mesh(), grid);
  const GaborNoise noise(field, o, Vec3::Constant(-1.1), Vec3::Constant(1.1));
  const std::vector<double> values = noise.sample(grid, mask);
  VoxelGrid part = grid;  // a sub-box with other block boundaries
  part.min = {-13, -7, 3};
  part.max = {20, 30, 17};
  const std::vector<double> partValues =
      noise.sample(part, std::vector<std::uint8_t>(part.count(), 1));
  const double sigma = std::sqrt(noise.shape().variance);
  int checked = 0;
  for (int k = part.min[2]; k <= part.max[2]; k += 3)
    for (int j = part.min[1]; j <= part.max[1]; j += 2)
      for (int i = part.min[0]; i <= part.max[0]; i += 5) {
        const double direct = noise.at(grid.centre(i, j, k));
        EXPECT_NEAR(partValues[part.offset(i, j, k)], direct, 1e-9 * sigma);
        if (mask[grid.offset(i, j, k)]) {
          EXPECT_NEAR(values[grid.offset(i, j, k)], direct, 1e-9 * sigma);
          ++checked;
        } else {
          EXPECT_EQ(values[grid.offset(i, j, k)], 0.0);
        }
      }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace tfd::core
