#include "io/volume/field_resample.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/point_locator.h"

namespace tfd::io {

namespace {

std::string formatNumber(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

VoxelLattice latticeForMesh(const core::TetMesh& mesh, double voxelSize, const core::Vec3& origin,
                            double maxVoxels) {
  if (!std::isfinite(voxelSize) || voxelSize <= 0) {
    throw core::Error("voxel size must be a finite number > 0, got " + formatNumber(voxelSize));
  }
  if (!origin.allFinite()) throw core::Error("voxel grid origin is not finite");
  VoxelLattice lattice;
  lattice.voxelSize = voxelSize;
  lattice.origin = origin;
  // A little slack so a centre that lies on the bounds up to rounding is still tried; the
  // point locator decides whether it is inside.
  constexpr double slack = 1e-9;
  double count = 1;
  std::array<double, 3> extent{};
  for (int a = 0; a < 3; ++a) {
    const double lo = std::ceil((mesh.boundsMin()[a] - origin[a]) / voxelSize - slack);
    const double hi = std::floor((mesh.boundsMax()[a] - origin[a]) / voxelSize + slack);
    if (!(hi >= lo)) {
      throw core::Error("voxel size " + formatNumber(voxelSize) +
                        " is too large for the mesh: no voxel centre falls inside its bounds "
                        "along axis " +
                        "xyz"[a]);
    }
    constexpr double intLimit = double(std::numeric_limits<int>::max()) / 2;
    if (std::abs(lo) > intLimit || std::abs(hi) > intLimit) {
      throw core::Error("voxel size " + formatNumber(voxelSize) +
                        " gives voxel indices out of range");
    }
    extent[a] = hi - lo + 1;
    count *= extent[a];
    lattice.min[a] = static_cast<int>(lo);
    lattice.max[a] = static_cast<int>(hi);
  }
  if (count > maxVoxels) {
    throw core::Error("voxel size " + formatNumber(voxelSize) + " gives " + formatNumber(count) +
                      " voxels (" + formatNumber(extent[0]) + " x " + formatNumber(extent[1]) +
                      " x " + formatNumber(extent[2]) + "), more than the limit of " +
                      formatNumber(maxVoxels) + "; use a larger voxel size");
  }
  return lattice;
}

VoxelSample sampleField(const core::TensorField& field, const core::Vec3& position) {
  VoxelSample sample;
  if (const auto location = field.mesh().locator().locate(position)) {
    sample.tet = location->tet;
    sample.barycentric = location->barycentric;
    sample.value = field.interpolate(location->tet, location->barycentric);
  }
  return sample;
}

VoxelSample RowSampler::operator()(const core::Vec3& position) {
  // Strictly inside: no other tet can have a larger smallest barycentric coordinate, so the
  // locator would pick this tet too, and the barycentric coordinates are computed the same way.
  constexpr double strict = 1e-9;
  constexpr int maxSteps = 4;
  const core::TetMesh& mesh = field_.mesh();
  int t = lastTet_;
  for (int step = 0; t >= 0 && step < maxSteps; ++step) {
    const Eigen::Vector4d b = mesh.barycentric(t, position);
    int worst = 0;
    const double smallest = b.minCoeff(&worst);
    if (smallest > strict) {
      lastTet_ = t;
      VoxelSample sample;
      sample.tet = t;
      sample.barycentric = b;
      sample.value = field_.interpolate(t, b);
      return sample;
    }
    if (smallest >= -strict) break;  // on or near a face: the locator breaks the tie
    const auto& across = mesh.faceTets()[mesh.tetFaces()[t][worst]];
    t = across[0] == t ? across[1] : across[0];  // −1 past the boundary
  }
  VoxelSample sample = sampleField(field_, position);
  lastTet_ = sample.tet >= 0 ? sample.tet : lastTet_;
  return sample;
}

std::vector<VoxelSample> sampleVoxels(const core::TensorField& field, const VoxelLattice& lattice,
                                      const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                                      const core::Progress& progress) {
  const int nx = std::max(0, hi[0] - lo[0] + 1);
  const int ny = std::max(0, hi[1] - lo[1] + 1);
  const int nz = std::max(0, hi[2] - lo[2] + 1);
  std::vector<VoxelSample> out(std::size_t(nx) * ny * nz);
  field.mesh().locator();  // build it once here rather than inside the first task
  tbb::parallel_for(0, ny * nz, [&](int row) {
    if (progress.cancelled()) return;
    const int j = lo[1] + row % ny;
    const int k = lo[2] + row / ny;
    VoxelSample* dst = out.data() + std::size_t(row) * nx;
    RowSampler sampler(field);
    for (int i = 0; i < nx; ++i) dst[i] = sampler(lattice.centre(lo[0] + i, j, k));
  });
  progress.throwIfCancelled();
  return out;
}

}  // namespace tfd::io
