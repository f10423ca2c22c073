#include "core/tensor.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tfd::core {
namespace {

constexpr double kSqrt2 = std::numbers::sqrt2;
const double kSqrt6 = std::sqrt(6.0);

/// Unit vector orthogonal to the rows of the rank-2 matrix m (largest cross product wins).
/// Returns false when m is (numerically) zero.
bool nullVectorOfRank2(const Mat3& m, Vec3& out) {
  const Vec3 r0 = m.row(0), r1 = m.row(1), r2 = m.row(2);
  const Vec3 c[3] = {r0.cross(r1), r0.cross(r2), r1.cross(r2)};
  int best = 0;
  double bestNorm = c[0].squaredNorm();
  for (int i = 1; i < 3; ++i) {
    if (const double n = c[i].squaredNorm(); n > bestNorm) bestNorm = n, best = i;
  }
  if (bestNorm <= 0) return false;
  out = c[best] / std::sqrt(bestNorm);
  return true;
}

/// Any unit vector pair (u, v) with (u, v, w) orthonormal.
void orthogonalComplement(const Vec3& w, Vec3& u, Vec3& v) {
  if (std::abs(w.x()) > std::abs(w.y())) {
    u = Vec3(-w.z(), 0, w.x()) / std::hypot(w.x(), w.z());
  } else {
    u = Vec3(0, w.z(), -w.y()) / std::hypot(w.y(), w.z());
  }
  v = w.cross(u);
}

/// Eigenvectors of `a` restricted to the plane spanned by u, v (closed-form 2x2 rotation, which
/// stays accurate however close the two eigenvalues are): `larger` for the larger eigenvalue.
void eigenvectorsInPlane(const Mat3& a, const Vec3& u, const Vec3& v, Vec3& larger,
                         Vec3& smaller) {
  const Vec3 au = a * u, av = a * v;
  const double theta = 0.5 * std::atan2(2 * u.dot(av), u.dot(au) - v.dot(av));
  const double c = std::cos(theta), s = std::sin(theta);
  larger = c * u + s * v;
  smaller = -s * u + c * v;
}

}  // namespace

Tensor Tensor::fromMatrix(const Mat3& m) {
  return {m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0)), 0.5 * (m(1, 2) + m(2, 1)),
          0.5 * (m(0, 2) + m(2, 0))};
}

Tensor Tensor::fromVec5(const std::array<double, 5>& v) {
  Tensor t;
  t.xx = v[0] / kSqrt2 + v[1] / kSqrt6;
  t.yy = -v[0] / kSqrt2 + v[1] / kSqrt6;
  t.zz = -2 * v[1] / kSqrt6;
  t.xy = v[2] / kSqrt2;
  t.xz = v[3] / kSqrt2;
  t.yz = v[4] / kSqrt2;
  return t;
}

Mat3 Tensor::matrix() const {
  Mat3 m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return m;
}

Tensor Tensor::deviator() const {
  const double mean = trace() / 3;
  return {xx - mean, yy - mean, zz - mean, xy, yz, xz};
}

double Tensor::norm() const {
  return std::sqrt(xx * xx + yy * yy + zz * zz + 2 * (xy * xy + yz * yz + xz * xz));
}

std::array<double, 5> Tensor::vec5() const {
  return {(xx - yy) / kSqrt2, (xx + yy - 2 * zz) / kSqrt6, kSqrt2 * xy, kSqrt2 * xz, kSqrt2 * yz};
}

Tensor& Tensor::operator+=(const Tensor& o) {
  xx += o.xx, yy += o.yy, zz += o.zz, xy += o.xy, yz += o.yz, xz += o.xz;
  return *this;
}
Tensor& Tensor::operator-=(const Tensor& o) {
  xx -= o.xx, yy -= o.yy, zz -= o.zz, xy -= o.xy, yz -= o.yz, xz -= o.xz;
  return *this;
}
Tensor& Tensor::operator*=(double s) {
  xx *= s, yy *= s, zz *= s, xy *= s, yz *= s, xz *= s;
  return *this;
}

EigenDecomposition eigenDecompose(const Tensor& t) {
  EigenDecomposition result;
  // Scale by the largest component so that squares neither overflow nor underflow.
  const auto c = t.components();
  double scale = 0;
  for (double v : c) scale = std::max(scale, std::abs(v));
  if (scale == 0) {
    result.values.setZero();
    result.vectors.setIdentity();
    return result;
  }
  const Tensor s = t * (1 / scale);
  const double mean = s.trace() / 3;
  const Tensor d = s.deviator();
  const double p = d.norm() / kSqrt6;  // sqrt(tr(D²)/6)
  if (p <= 1e-300) {                   // a multiple of the identity: every vector is an eigenvector
    result.values.setConstant(mean * scale);
    result.vectors.setIdentity();
    return result;
  }
  // Eigenvalues of B = D/p are 2cos(φ + 2πk/3) with cos(3φ) = det(B)/2 (trigonometric solution).
  const Mat3 b = d.matrix() / p;
  const double halfDet = std::clamp(b.determinant() / 2, -1.0, 1.0);
  const double phi = std::acos(halfDet) / 3;
  constexpr double kTwoThirdsPi = 2 * std::numbers::pi / 3;
  const double beta1 = 2 * std::cos(phi), beta3 = 2 * std::cos(phi + kTwoThirdsPi);

  // Eigenvectors of B: first that of the most isolated eigenvalue (accurate, because the
  // trigonometric solution is accurate for it), then the other two inside its orthogonal
  // complement; eigenvalues as Rayleigh quotients, accurate to rounding.
  Vec3 e1, e2, e3, u, v, larger, smaller;
  const Mat3 identity = Mat3::Identity();
  if (halfDet >= 0) {  // β1 − β2 ≥ β2 − β3: β1 is the most isolated
    if (!nullVectorOfRank2(b - beta1 * identity, e1)) e1 = Vec3::UnitX();
    orthogonalComplement(e1, u, v);
    eigenvectorsInPlane(b, u, v, larger, smaller);
    e2 = larger;
    e3 = e1.cross(e2);
  } else {
    if (!nullVectorOfRank2(b - beta3 * identity, e3)) e3 = Vec3::UnitZ();
    orthogonalComplement(e3, u, v);
    eigenvectorsInPlane(b, u, v, larger, smaller);
    e2 = smaller;
    e1 = e2.cross(e3);
  }
  Mat3& vectors = result.vectors;
  vectors << e1, e2, e3;
  const Mat3 sm = s.matrix();
  for (int i = 0; i < 3; ++i) {
    result.values[i] = vectors.col(i).dot(sm * vectors.col(i)) * scale;
  }
  // Rayleigh quotients of nearly equal eigenvalues may swap order: restore it, keeping the
  // frame right-handed.
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < 2; ++i) {
      if (result.values[i] < result.values[i + 1]) {
        std::swap(result.values[i], result.values[i + 1]);
        vectors.col(i).swap(vectors.col(i + 1));
        vectors.col(2) = -vectors.col(2);
      }
    }
  }
  return result;
}

TensorType classify(const Tensor& t, double relativeTolerance) {
  const Tensor a = t.deviator();
  const double n = a.norm();
  const double lambda2 = eigenDecompose(a).values[1];
  if (n == 0 || std::abs(lambda2) <= relativeTolerance * n) return TensorType::Neutral;
  return lambda2 < 0 ? TensorType::Linear : TensorType::Planar;
}

const char* toString(TensorType type) {
  switch (type) {
    case TensorType::Linear: return "linear";
    case TensorType::Planar: return "planar";
    case TensorType::Neutral: return "neutral";
  }
  return "?";
}

double discriminant(const Tensor& t) {
  const Mat3 a = t.deviator().matrix();
  const double j2 = 0.5 * (a * a).trace();
  const double j3 = a.determinant();
  return std::max(0.0, 4 * j2 * j2 * j2 - 27 * j3 * j3);
}

double normalizedDiscriminant(const Tensor& t) {
  const Tensor a = t.deviator();
  const double n = a.norm();
  if (n == 0) return 0;
  return discriminant(a * (1 / n));
}

double mode(const Tensor& t) {
  const Tensor a = t.deviator();
  const double n = a.norm();
  if (n == 0) return 0;
  return std::clamp(3 * kSqrt6 * (a * (1 / n)).matrix().determinant(), -1.0, 1.0);
}

}  // namespace tfd::core
