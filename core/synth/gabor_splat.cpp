// GaborNoise::sample: every impulse splatted into blocks of voxels. The kernel is separable,
//     exp(−πa²|d|²) e^{i(ω·d + φ)} = e^{iφ} Π_axis exp(−πa² d_a²) e^{i ω_a d_a},
// so per impulse and block three short tables (one per axis) are filled by recurrences
// (the Gaussian ratio and the phasor rotation from one voxel to the next), and each voxel costs
// a complex product of table entries.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <numbers>

#include "core/synth/gabor_noise.h"

namespace tfd::core {

namespace {

constexpr int kBlock = 16;
using Complex = std::complex<double>;

/// table[t] = exp(−A d_t²) e^{i w d_t} with d_t = d0 + t h, t = 0 … n−1.
void axisTable(double d0, double h, double A, double w, int n, Complex* table) {
  double g = std::exp(-A * d0 * d0);
  double ratio = std::exp(-A * (2 * d0 * h + h * h));
  const double q = std::exp(-2 * A * h * h);
  Complex phasor = std::polar(1.0, w * d0);
  const Complex step = std::polar(1.0, w * h);
  for (int t = 0; t < n; ++t) {
    table[t] = g * phasor;
    g *= ratio;
    ratio *= q;
    phasor *= step;
  }
}

}  // namespace

std::vector<double> GaborNoise::sample(const VoxelGrid& grid, const std::vector<std::uint8_t>& mask,
                                       const Progress& progress, std::size_t* evaluations) const {
  const auto dims = grid.dims();
  std::vector<double> out(grid.count(), 0.0);
  const int nb[3] = {(dims[0] + kBlock - 1) / kBlock, (dims[1] + kBlock - 1) / kBlock,
                     (dims[2] + kBlock - 1) / kBlock};
  const double h = grid.voxelSize, r = shape_.radius, r2 = r * r;
  const double A = std::numbers::pi * shape_.a * shape_.a;
  std::atomic<std::size_t> total{0};

  tbb::parallel_for(0, nb[0] * nb[1] * nb[2], [&](int b) {
    if (progress.cancelled()) return;
    const int lo[3] = {grid.min[0] + (b % nb[0]) * kBlock,
                       grid.min[1] + (b / nb[0] % nb[1]) * kBlock,
                       grid.min[2] + (b / (nb[0] * nb[1])) * kBlock};
    const int hi[3] = {std::min(lo[0] + kBlock - 1, grid.max[0]),
                       std::min(lo[1] + kBlock - 1, grid.max[1]),
                       std::min(lo[2] + kBlock - 1, grid.max[2])};
    const int n[3] = {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
    bool any = false;
    for (int k = lo[2]; k <= hi[2] && !any; ++k)
      for (int j = lo[1]; j <= hi[1] && !any; ++j)
        for (int i = lo[0]; i <= hi[0] && !any; ++i) any = mask[grid.offset(i, j, k)] != 0;
    if (!any) return;

    std::vector<double> acc(std::size_t(n[0]) * n[1] * n[2], 0.0);
    Complex tx[kBlock], ty[kBlock], tz[kBlock];
    std::size_t count = 0;
    const Vec3 bmin = grid.centre(lo[0], lo[1], lo[2]), bmax = grid.centre(hi[0], hi[1], hi[2]);
    const auto cl = cellOf(bmin - Vec3::Constant(r)), ch = cellOf(bmax + Vec3::Constant(r));
    for (int cz = cl[2]; cz <= ch[2]; ++cz)
      for (int cy = cl[1]; cy <= ch[1]; ++cy)
        for (int cx = cl[0]; cx <= ch[0]; ++cx) {
          const std::size_t cell = cellIndex(cx, cy, cz);
          for (std::size_t s = cellStart_[cell]; s < cellStart_[cell + 1]; ++s) {
            const GaborImpulse& k = impulses_[s];
            const Vec3 c = k.centre;
            const Vec3 gap = (bmin - c).cwiseMax(c - bmax).cwiseMax(0.0);
            if (gap.squaredNorm() > r2) continue;
            const Vec3 d0 = bmin - c;  // offset of the block's first voxel from the centre
            axisTable(d0.x(), h, A, k.omega.x(), n[0], tx);
            axisTable(d0.y(), h, A, k.omega.y(), n[1], ty);
            axisTable(d0.z(), h, A, k.omega.z(), n[2], tz);
            const Complex start = std::polar(1.0, k.phase);
            for (int z = 0; z < n[2]; ++z) {
              const double dz = d0.z() + h * z, rz2 = r2 - dz * dz;
              if (rz2 < 0) continue;
              const Complex fz = start * tz[z];
              for (int y = 0; y < n[1]; ++y) {
                const double dy = d0.y() + h * y, ry2 = rz2 - dy * dy;
                if (ry2 < 0) continue;
                const double rx = std::sqrt(ry2);
                const int x0 = std::max(0, int(std::ceil((c.x() - rx - bmin.x()) / h)));
                const int x1 = std::min(n[0] - 1, int(std::floor((c.x() + rx - bmin.x()) / h)));
                if (x0 > x1) continue;
                const Complex f = fz * ty[y];
                double* row = acc.data() + (std::size_t(z) * n[1] + y) * n[0];
                for (int x = x0; x <= x1; ++x) {
                  // |d|² ≤ r² again per voxel: the row bounds above are rounded.
                  const double dx = d0.x() + h * x;
                  if (dx * dx > ry2) continue;
                  row[x] += f.real() * tx[x].real() - f.imag() * tx[x].imag();
                }
                count += std::size_t(x1 - x0 + 1);
              }
            }
          }
        }
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const std::size_t v = grid.offset(lo[0] + x, lo[1] + y, lo[2] + z);
          if (mask[v]) out[v] = acc[(std::size_t(z) * n[1] + y) * n[0] + x];
        }
    total += count;
  });
  progress.throwIfCancelled();
  if (evaluations) *evaluations = total.load();
  return out;
}

}  // namespace tfd::core
