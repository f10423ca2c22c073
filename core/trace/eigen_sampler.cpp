#include "core/trace/eigen_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/point_locator.h"

namespace tfd::core {

double relativeEigenGap(const Vec3& l, EigenFamily family) {
  // The deviator has the same eigen-gaps; its Frobenius norm from the eigenvalues.
  const double mean = l.sum() / 3;
  const double norm = (l.array() - mean).matrix().norm();
  if (!(norm > 0)) return 0;
  const double upper = l[0] - l[1], lower = l[1] - l[2];
  switch (family) {
    case EigenFamily::Major:
      return upper / norm;
    case EigenFamily::Medium:
      return std::min(upper, lower) / norm;
    case EigenFamily::Minor:
      return lower / norm;
  }
  return 0;
}

EigenSampler::EigenSampler(const TensorField& field, EigenFamily family)
    : field_(field), family_(family) {}

std::optional<EigenSample> EigenSampler::sample(const Vec3& p) const {
  const auto location = field_.mesh().locator().locate(p);
  if (!location) return std::nullopt;
  const Tensor t = field_.interpolate(location->tet, location->barycentric);
  const EigenDecomposition e = eigenDecompose(t);
  EigenSample s;
  s.direction = e.vectors.col(static_cast<int>(family_));
  s.eigenvalues = e.values;
  s.gap = relativeEigenGap(e.values, family_);
  return s;
}

}  // namespace tfd::core
