#include "core/topology/tet_conic.h"

#include <algorithm>

namespace tfd::core::topology {

TetLinearField::TetLinearField(const std::array<Vec3, 4>& corners,
                               const std::array<Tensor, 4>& tensors) {
  centre = (corners[0] + corners[1] + corners[2] + corners[3]) / 4;
  size = 0;
  for (const Vec3& c : corners) size = std::max(size, (c - centre).norm());
  if (size == 0) size = 1;
  std::array<Vec5, 4> t;
  for (int i = 0; i < 4; ++i) {
    t[i] = toVec5(tensors[i]);
    scale = std::max(scale, t[i].norm());
  }
  Mat3 e;
  for (int i = 0; i < 3; ++i) e.col(i) = (corners[i + 1] - corners[0]) / size;
  toBarycentric = e.inverse();
  q0 = local(corners[0]);
  if (scale == 0) return;
  value = (t[0] + t[1] + t[2] + t[3]) / (4 * scale);
  for (int k = 0; k < 3; ++k) {
    gradient[k].setZero();
    for (int i = 0; i < 3; ++i) gradient[k] += toBarycentric(i, k) * (t[i + 1] - t[0]) / scale;
  }
}

Eigen::Vector4d TetLinearField::barycentric(const Vec3& p) const {
  const Vec3 l = toBarycentric * (local(p) - q0);
  return Eigen::Vector4d(1 - l.sum(), l[0], l[1], l[2]);
}

std::array<Mat3, 3> TetLinearField::gradientMatrices() const {
  return {matrixOf(gradient[0]), matrixOf(gradient[1]), matrixOf(gradient[2])};
}

TetConic::TetConic(const TetLinearField& field) : field_(field) {
  if (field.scale == 0) return;
  Eigen::Matrix<double, 5, 4> m;
  m << field.value, field.gradient[0], field.gradient[1], field.gradient[2];
  for (int i = 0; i < 4; ++i) {
    columnNorms_[i] = m.col(i).norm();
    if (columnNorms_[i] == 0) return;
    m.col(i) /= columnNorms_[i];
  }
  const Eigen::HouseholderQR<Eigen::Matrix<double, 5, 4>> qr(m);
  r_ = qr.matrixQR().topRows<4>().triangularView<Eigen::Upper>();
  for (int i = 1; i < 4; ++i)
    if (std::abs(r_(i, i)) < 1e-10) return;
  const Eigen::Matrix<double, 5, 5> q = qr.householderQ() * Eigen::Matrix<double, 5, 5>::Identity();
  q_ = q.leftCols<4>();
  n_ = matrixOf(q.col(4));
  chart_ = conicChart(n_);
  valid_ = chart_.conditioning > 1e-9;
}

ConicPoint TetConic::point(double theta) const {
  ConicPoint p;
  if (!valid_) return p;
  const Vec3 v = chart_.at(theta);
  const Eigen::Vector4d x = r_.triangularView<Eigen::Upper>()
                                .solve(q_.transpose() * veronese(v))
                                .cwiseQuotient(columnNorms_);
  if (!(std::abs(x[0]) > 1e-13 * x.norm())) return p;
  p.finite = true;
  p.position = field_.centre + field_.size * Vec3(x[1], x[2], x[3]) / x[0];
  const double len2 = v.squaredNorm();
  p.eigenvector = v / std::sqrt(len2);
  p.sigma = len2 / x[0];
  return p;
}

}  // namespace tfd::core::topology
