#pragma once
// Fields whose degenerate curves are known exactly, for the removal tests and benchmarks.
//
// T(p) = 2 e eᵀ − (I − e eᵀ) + f (u uᵀ − w wᵀ) + g (u wᵀ + w uᵀ), with (u, w, e) orthonormal and
// W = f + i g a complex function of the position. In the frame (e, u, w) the eigenvalues are 2
// along e and −1 ± |W| in the (u, w) plane, so as long as |W| < 3 the field is degenerate
// (linear, e the non-repeating eigenvector) exactly where W = 0. A curve of W = 0 with tangent
// t is a wedge or a trisector by the sign of e · (∇f × ∇g), with a transition where t ⊥ e, so
// with a constant e a loop always has wedge and trisector parts (the one-loop scenario).
#include <cmath>
#include <complex>
#include <functional>
#include <memory>

#include "core/tensor_field.h"

namespace tfd::core::testing {

using Complex = std::complex<double>;

struct Frame {
  Vec3 e, u, w;
};

/// A generic constant frame: e tilted off every axis and mesh plane.
inline Frame tiltedFrame() {
  const Vec3 e = Vec3(0.3, 0.5, 1).normalized();
  const Vec3 u = e.cross(Vec3(0.2, 1, 0.1)).normalized();
  return {e, u, e.cross(u)};
}

inline Tensor designedTensor(const Frame& fr, Complex W) {
  const Mat3 E = fr.e * fr.e.transpose(), U = fr.u * fr.u.transpose(), Wm = fr.w * fr.w.transpose(),
             UW = fr.u * fr.w.transpose();
  const Mat3 m =
      2 * E - (Mat3::Identity() - E) + W.real() * (U - Wm) + W.imag() * (UW + UW.transpose());
  return Tensor::fromMatrix(m).deviator();
}

inline TensorField designedField(std::shared_ptr<const TetMesh> mesh,
                                 const std::function<Complex(const Vec3&)>& W,
                                 const std::function<Frame(const Vec3&)>& frame = {}) {
  std::vector<Tensor> values;
  values.reserve(mesh->vertexCount());
  for (const Vec3& p : mesh->positions())
    values.push_back(designedTensor(frame ? frame(p) : tiltedFrame(), W(p)));
  return TensorField(std::move(mesh), std::move(values));
}

/// One mixed loop: the circle x² + z² = r² in the plane y = 0.
inline Complex loopW(const Vec3& p, double r = 0.4) {
  return {p.x() * p.x() + p.z() * p.z() - r * r, p.y()};
}
/// One open curve with a wedge end and a trisector end: the parabola z = 0.3 − x², y = 0.
inline Complex arcW(const Vec3& p) { return {p.x() * p.x() + p.z() - 0.3, p.y()}; }
/// Two straight open curves x = ±a, y = 0 along z: a pure wedge and a pure trisector.
inline Complex twoLinesW(const Vec3& p, double a = 0.3) { return {p.x() * p.x() - a * a, p.y()}; }
/// The loop of loopW threaded by the y axis (x = z = 0): the loop's ball must cut the line.
inline Complex linkedW(const Vec3& p, double r = 0.45) {
  return 0.5 * Complex(p.x(), p.z()) * Complex(p.x() * p.x() + p.z() * p.z() - r * r, p.y());
}

/// On a solid torus around the z axis: the frame e = φ̂, u = ρ̂, w = ẑ turns with the core
/// circle ρ = R, z = 0, which is then a pure (wedge or trisector) loop.
inline Frame turningFrame(const Vec3& p) {
  const Vec3 rho = Vec3(p.x(), p.y(), 0).normalized();
  return {Vec3(-rho.y(), rho.x(), 0), rho, Vec3(0, 0, 1)};
}
inline Complex coreCircleW(const Vec3& p, double R = 0.6) {
  return {std::hypot(p.x(), p.y()) - R, p.z()};
}

/// A smooth frame on any domain (no axis to avoid) under which circles around the z axis are
/// pure loops: e = (−y, x, k) normalised turns with the circles but tilts towards ẑ by k (so e ·
/// φ̂ = ρ / √(ρ² + k²) > 0 off the axis, and e = ẑ on it), u is x̂ projected off e (never
/// parallel to e, whose z component is positive), w = e × u.
inline Frame swirlFrame(const Vec3& p, double k = 0.3) {
  const Vec3 e = Vec3(-p.y(), p.x(), k).normalized();
  const Vec3 u = (Vec3::UnitX() - e.x() * e).normalized();
  return {e, u, e.cross(u)};
}
/// Circles around the z axis in the plane z = z0, radii r1 < r2, one pure wedge and one pure
/// trisector (the inner one the trisector when `innerTrisector`) under turningFrame or
/// swirlFrame. Scaled by 10 and bounded to |W| < 1 by a positive factor (zero set and patterns
/// unchanged): between the circles the product is small, and the linear interpolation of a
/// turning frame across an edge would otherwise add degenerate points of its own.
inline Complex twoCirclesW(const Vec3& p, double r1, double r2, double z0 = 0,
                           bool innerTrisector = false) {
  const double rho = std::hypot(p.x(), p.y());
  Complex inner(rho - r1, p.z() - z0), outer(rho - r2, p.z() - z0);
  (innerTrisector ? inner : outer) = std::conj(innerTrisector ? inner : outer);
  const Complex w = 10.0 * inner * outer;
  return w / std::sqrt(1 + std::norm(w));
}

}  // namespace tfd::core::testing
