#include "core/topology/face_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/topology/conic_chart.h"
#include "core/topology/traceless5.h"
#include "core/topology/trig_roots.h"

namespace tfd::core::topology {
namespace {

using Mat53 = Eigen::Matrix<double, 5, 3>;
using Mat5 = Eigen::Matrix<double, 5, 5>;

constexpr double kRankTolerance = 1e-10;      // relative, on unit-normalised columns
constexpr double kPencilTolerance = 1e-10;    // |mode| of the best pencil member
constexpr double kDuplicateTolerance = 1e-8;  // barycentric distance of merged roots

/// g(θ) = A0 + A1 cos θ + B1 sin θ + A2 cos 2θ + B2 sin 2θ.
struct TrigQuadratic {
  double a0, a1, b1, a2, b2;
  double value(double t) const {
    return a0 + a1 * std::cos(t) + b1 * std::sin(t) + a2 * std::cos(2 * t) + b2 * std::sin(2 * t);
  }
  double derivative(double t) const {
    return -a1 * std::sin(t) + b1 * std::cos(t) - 2 * a2 * std::sin(2 * t) +
           2 * b2 * std::cos(2 * t);
  }
  double scale() const {
    return std::abs(a0) + std::abs(a1) + std::abs(b1) + std::abs(a2) + std::abs(b2);
  }
};

/// Newton on A(s,t) − σ b(v) = 0 with unknowns (s, t, σ, two tangent components of v).
/// Returns false when it does not converge or the Jacobian is singular (grazing curve).
bool polish(const Vec5& t0, const Vec5& t1, const Vec5& t2, double& s, double& t, double& sigma,
            Vec3& v, bool& illConditioned) {
  illConditioned = false;
  double bestResidual = (t0 + s * t1 + t * t2 - sigma * veronese(v)).norm();
  for (int iteration = 0; iteration < 8; ++iteration) {
    Vec3 e1, e2;
    completeFrame(v, e1, e2);
    const Vec5 f = t0 + s * t1 + t * t2 - sigma * veronese(v);
    Mat5 j;
    j.col(0) = t1;
    j.col(1) = t2;
    j.col(2) = -veronese(v);
    j.col(3) = -sigma * veroneseDerivative(v, e1);
    j.col(4) = -sigma * veroneseDerivative(v, e2);
    const Eigen::FullPivLU<Mat5> lu(j);
    if (!lu.isInvertible() || lu.rcond() < 1e-13) {
      illConditioned = true;
      return bestResidual < 1e-13;
    }
    if (lu.rcond() < 1e-10) illConditioned = true;
    const Eigen::Matrix<double, 5, 1> dx = lu.solve(-f);
    double ns = s + dx[0], nt = t + dx[1], nsigma = sigma + dx[2];
    Vec3 nv = v + dx[3] * e1 + dx[4] * e2;
    const double len2 = nv.squaredNorm();
    nsigma *= len2;  // σ b(v) = σ |v|² b(v/|v|)
    nv /= std::sqrt(len2);
    const double residual = (t0 + ns * t1 + nt * t2 - nsigma * veronese(nv)).norm();
    if (!(residual <= bestResidual * 1.5 + 1e-15)) break;  // diverging: keep the last good one
    s = ns, t = nt, sigma = nsigma, v = nv;
    bestResidual = std::min(bestResidual, residual);
    if (dx.norm() < 1e-15 * (1 + std::abs(s) + std::abs(t) + std::abs(sigma)) || residual < 1e-16)
      break;
  }
  return bestResidual < 1e-12;
}

/// Newton steps (clamped to ±0.25) on g(θ) = 0 from θ; true when |g| reaches the tolerance.
bool refineRoot(const TrigQuadratic& g, double gScale, double& theta) {
  bool converged = false;
  for (int it = 0; it < 12; ++it) {
    const double value = g.value(theta), slope = g.derivative(theta);
    if (std::abs(value) <= 1e-15 * gScale) {
      converged = true;
      break;
    }
    if (slope == 0) break;
    const double step = std::clamp(value / slope, -0.25, 0.25);
    theta -= step;
    if (std::abs(step) < 1e-15) {
      converged = std::abs(g.value(theta)) <= 1e-11 * gScale;
      break;
    }
  }
  if (!converged) converged = std::abs(g.value(theta)) <= 1e-11 * gScale;
  return converged;
}

}  // namespace

FaceSolution solveFace(const Tensor& a, const Tensor& b, const Tensor& c,
                       const FaceSolverOptions& options) {
  FaceSolution out;
  const Tensor da = a.deviator(), db = b.deviator(), dc = c.deviator();
  const double scale = std::max({da.norm(), db.norm(), dc.norm()});
  if (scale == 0) {
    out.flags |= kFaceZero;
    return out;
  }
  const Vec5 t0 = toVec5(da) / scale;
  const Vec5 t1 = (toVec5(db) - toVec5(da)) / scale;
  const Vec5 t2 = (toVec5(dc) - toVec5(da)) / scale;
  const double norms[3] = {t0.norm(), t1.norm(), t2.norm()};
  if (norms[0] == 0 || norms[1] == 0 || norms[2] == 0) {
    out.flags |= kFaceRankDeficient;
    return out;
  }
  // QR of unit-normalised columns: the diagonal of R measures linear independence.
  Mat53 m;
  m << t0 / norms[0], t1 / norms[1], t2 / norms[2];
  const Eigen::HouseholderQR<Mat53> qr(m);
  const Eigen::Matrix3d r = qr.matrixQR().topRows<3>().triangularView<Eigen::Upper>();
  if (std::abs(r(1, 1)) < kRankTolerance || std::abs(r(2, 2)) < kRankTolerance) {
    out.flags |= kFaceRankDeficient;
    return out;
  }
  const Mat5 q = qr.householderQ() * Mat5::Identity();
  const Vec5 n1 = q.col(3), n2 = q.col(4);

  // Best-conditioned pencil member: largest |det| of the unit-norm cos φ N1 + sin φ N2
  // (|det| ∝ |λ1 λ2 λ3| vanishes exactly for line pairs).
  const Mat3 m1 = matrixOf(n1), m2 = matrixOf(n2);
  double bestDet = -1, bestPhi = 0;
  constexpr int kSamples = 24;
  for (int k = 0; k < kSamples; ++k) {
    const double phi = std::numbers::pi * k / kSamples;
    const double d = std::abs((std::cos(phi) * m1 + std::sin(phi) * m2).determinant());
    if (d > bestDet) bestDet = d, bestPhi = phi;
  }
  if (3 * std::sqrt(6.0) * bestDet < kPencilTolerance) {
    out.flags |= kFaceDegeneratePencil;
    return out;
  }
  const double cphi = std::cos(bestPhi), sphi = std::sin(bestPhi);
  const ConicChart chart = conicChart(cphi * m1 + sphi * m2);
  if (chart.conditioning == 0) {
    out.flags |= kFaceDegeneratePencil;
    return out;
  }
  const Mat3 nb = -sphi * m1 + cphi * m2;
  const Vec3 nbc = nb * chart.qc, nb1 = nb * chart.q1, nb2 = nb * chart.q2;
  const double mcc = chart.qc.dot(nbc), mc1 = chart.qc.dot(nb1), mc2 = chart.qc.dot(nb2);
  const double m11 = chart.q1.dot(nb1), m22 = chart.q2.dot(nb2), m12 = chart.q1.dot(nb2);
  const double aa = chart.a, bb = chart.b;
  const TrigQuadratic g{mcc + (aa * aa * m11 + bb * bb * m22) / 2, 2 * aa * mc1, 2 * bb * mc2,
                        (aa * aa * m11 - bb * bb * m22) / 2, aa * bb * m12};
  const double gScale = g.scale();

  std::array<TrigRoot, 4> roots;
  const int rootCount = trigQuadraticRoots(g.a0, g.a1, g.b1, g.a2, g.b2, roots);

  // Least squares b(v) = α T0 + β T1 + γ T2 through the QR of the normalised columns.
  const auto coefficients = [&](const Vec3& v) -> Eigen::Vector3d {
    const Vec5 y = veronese(v);
    const Eigen::Vector3d qty = (q.leftCols<3>().transpose() * y);
    Eigen::Vector3d x = r.triangularView<Eigen::Upper>().solve(qty);
    return Eigen::Vector3d(x[0] / norms[0], x[1] / norms[1], x[2] / norms[2]);
  };

  for (int i = 0; i < rootCount; ++i) {
    double theta = roots[i].theta;
    const bool converged = refineRoot(g, gScale, theta);
    const bool real = roots[i].isolated || converged;

    Vec3 v = chart.at(theta).normalized();
    const Eigen::Vector3d x = coefficients(v);
    if (!(std::abs(x[0]) > 1e-12 * x.norm())) continue;  // point at infinity
    double s = x[1] / x[0], t = x[2] / x[0], sigma = 1 / x[0];
    if (!real) {
      // A near-double root that does not cross zero: the curve grazes the plane here.
      if (std::min({1 - s - t, s, t}) > -1e-3) out.flags |= kFaceTangency;
      continue;
    }
    if (std::min({1 - s - t, s, t}) < -0.05) continue;  // clearly outside: skip polishing
    bool illConditioned = false;
    if (!polish(t0, t1, t2, s, t, sigma, v, illConditioned)) {
      if (std::min({1 - s - t, s, t}) > -1e-6) out.flags |= kFacePolishFailed;
      continue;
    }
    const Vec3 bary(1 - s - t, s, t);
    const double minBary = bary.minCoeff();
    if (minBary < -options.edgeTolerance) continue;
    if (illConditioned) out.flags |= kFaceTangency;
    if (minBary <= options.edgeTolerance) out.flags |= kFaceNearEdge;
    bool duplicate = false;
    for (int k = 0; k < out.count; ++k) {
      if ((out.points[k].barycentric - bary).cwiseAbs().maxCoeff() < kDuplicateTolerance) {
        duplicate = true;  // two roots polished onto one point: a double root
        out.flags |= kFaceTangency;
      }
    }
    if (duplicate || out.count == 4) continue;
    FacePoint& p = out.points[out.count++];
    p.barycentric = bary;
    p.eigenvector = v;
    p.sigma = sigma;
  }
  return out;
}

}  // namespace tfd::core::topology
