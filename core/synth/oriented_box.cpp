#include "core/synth/oriented_box.h"

#include <cmath>

namespace tfd::core {

bool boxesOverlap(const OrientedBox& a, const OrientedBox& b) {
  // Work in a's frame: R = a.axesᵀ b.axes takes b's axes to a's, t is b's centre in a's frame.
  const Mat3 r = a.axes.transpose() * b.axes;
  const Vec3 t = a.axes.transpose() * (b.centre - a.centre);
  Mat3 absR;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) absR(i, j) = std::abs(r(i, j)) + 1e-12;
  const Vec3& ea = a.half;
  const Vec3& eb = b.half;
  // a's face normals.
  for (int i = 0; i < 3; ++i) {
    const double rb = eb[0] * absR(i, 0) + eb[1] * absR(i, 1) + eb[2] * absR(i, 2);
    if (std::abs(t[i]) > ea[i] + rb) return false;
  }
  // b's face normals.
  for (int j = 0; j < 3; ++j) {
    const double ra = ea[0] * absR(0, j) + ea[1] * absR(1, j) + ea[2] * absR(2, j);
    const double proj = t[0] * r(0, j) + t[1] * r(1, j) + t[2] * r(2, j);
    if (std::abs(proj) > ra + eb[j]) return false;
  }
  // Cross products a_i × b_j, expressed in a's frame.
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = ea[i1] * absR(i2, j) + ea[i2] * absR(i1, j);
      const double rb = eb[j1] * absR(i, j2) + eb[j2] * absR(i, j1);
      const double proj = t[i2] * r(i1, j) - t[i1] * r(i2, j);
      if (std::abs(proj) > ra + rb) return false;
    }
  }
  return true;
}

}  // namespace tfd::core
