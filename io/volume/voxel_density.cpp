#include "io/volume/voxel_density.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tfd::io {

double degeneracyCloseness(const core::Tensor& t) {
  return 2 / std::numbers::pi * std::abs(std::asin(core::mode(t)));
}

VoxelScalarFunction voxelDensityFunction(VoxelDensity measure, const core::TensorField& field) {
  switch (measure) {
    case VoxelDensity::None:
      return nullptr;
    case VoxelDensity::Degeneracy:
      return [](const core::Vec3&, const VoxelSample& s) { return degeneracyCloseness(s.value); };
    case VoxelDensity::Anisotropy: {
      // The interpolated deviator's norm is at most the largest vertex norm (convexity), so
      // the ratio stays in [0, 1].
      double largest = 0;
      for (const core::Tensor& t : field.values()) largest = std::max(largest, t.deviator().norm());
      const double scale = largest > 0 ? 1 / largest : 0;
      return [scale](const core::Vec3&, const VoxelSample& s) {
        return std::min(1.0, s.value.deviator().norm() * scale);
      };
    }
  }
  return nullptr;
}

std::array<float, 3> previewColour(double v) {
  static constexpr float kStops[4][3] = {
      {0.05f, 0.05f, 0.35f}, {0.0f, 0.55f, 0.6f}, {0.75f, 0.85f, 0.15f}, {1.0f, 0.95f, 0.6f}};
  const double x = std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0) * 3;
  const int i = std::min(int(x), 2);
  const float f = float(x - i);
  std::array<float, 3> rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c]);
  return rgb;
}

}  // namespace tfd::io
