#pragma once
// Shared by the element-synthesis tests: an independent box-overlap oracle and analytic fields.
#include <array>
#include <cmath>

#include "core/structured_mesh.h"
#include "core/synth/oriented_box.h"
#include "core/tensor_field.h"

namespace tfd::core::test {

/// The separating-axis theorem written the plain way: project the 8 corners of both boxes on
/// each of the 15 axes (face normals, edge cross products; vanishing ones skipped) and look for
/// a gap. Independent of the optimised formulation in core/synth/oriented_box.cpp.
inline bool cornersOverlap(const OrientedBox& a, const OrientedBox& b) {
  auto corners = [](const OrientedBox& box) {
    std::array<Vec3, 8> out;
    for (int c = 0; c < 8; ++c) {
      Vec3 p = box.centre;
      for (int i = 0; i < 3; ++i) p += ((c >> i) & 1 ? 1.0 : -1.0) * box.half[i] * box.axes.col(i);
      out[c] = p;
    }
    return out;
  };
  const auto ca = corners(a), cb = corners(b);
  std::vector<Vec3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(a.axes.col(i)), axes.push_back(b.axes.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = a.axes.col(i).cross(b.axes.col(j));
      if (c.norm() > 1e-9) axes.push_back(c.normalized());
    }
  for (const Vec3& n : axes) {
    double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
    for (const Vec3& p : ca) loA = std::min(loA, n.dot(p)), hiA = std::max(hiA, n.dot(p));
    for (const Vec3& p : cb) loB = std::min(loB, n.dot(p)), hiB = std::max(hiB, n.dot(p));
    if (hiA < loB || hiB < loA) return false;
  }
  return true;
}

/// An affine traceless field (exact under linear interpolation): linear (λ2 < 0) for x above
/// about 0.1 and planar below, with a frame that turns across the box.
inline Tensor affineTwoRegionField(const Vec3& p) {
  const double x = p.x(), y = p.y(), z = p.z();
  return Tensor{2 * x, -x + 0.3, -x - 0.3, 0.4 * y + 0.1, 0.3 * z, 0.2 + 0.2 * x};
}

/// `f` sampled at the vertices of an n³ structured box [lo, hi].
template <class F>
TensorField sampledField(int n, const Vec3& lo, const Vec3& hi, F&& f) {
  auto mesh = makeBoxMesh(n, n, n, lo, hi);
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) values.push_back(f(p));
  return TensorField(mesh, std::move(values));
}

}  // namespace tfd::core::test
