// Design elements (paper §5, "Design", Equations 2 and 3).
#include "core/design/design_element.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.h"

namespace tfd::core {

namespace {

void checkFrame(const Mat3& frame, const char* what) {
  if (!frame.allFinite()) throw Error(std::string(what) + ": the frame is not finite");
  const double defect = (frame.transpose() * frame - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (defect > 1e-6) {
    std::ostringstream out;
    out << what << ": the frame is not orthonormal (|RᵀR − I| = " << defect << ")";
    throw Error(out.str());
  }
}

Tensor diagonal(double a, double b, double c) { return Tensor{a, b, c, 0, 0, 0}; }

}  // namespace

Tensor LocalLinearization::evaluate(const Vec3& p) const {
  // Equation 2 in the element's frame: d are the local coordinates of p − x0.
  const Vec3 d = frame.transpose() * (p - origin);
  Tensor local = value;
  for (int i = 0; i < 3; ++i) local += jacobian[i] * d[i];
  return local.rotated(frame).deviator();
}

LocalLinearization makeTensorLinearization(const Vec3& origin, const Mat3& frame,
                                           const Vec3& eigenvalues) {
  checkFrame(frame, "tensor design element");
  if (!eigenvalues.allFinite()) throw Error("tensor design element: eigenvalues are not finite");
  if (!origin.allFinite()) throw Error("tensor design element: position is not finite");
  LocalLinearization result;
  result.origin = origin;
  result.frame = frame;
  result.value = diagonal(eigenvalues[0], eigenvalues[1], eigenvalues[2]).deviator();
  return result;
}

LocalLinearization makeDegenerateLinearization(const Vec3& origin, const Mat3& frame,
                                               DegenerateType type, DegeneratePattern pattern) {
  checkFrame(frame, "degenerate design element");
  if (!origin.allFinite()) throw Error("degenerate design element: position is not finite");
  if (pattern == DegeneratePattern::Transition)
    throw Error("degenerate design element: the pattern must be wedge or trisector");
  LocalLinearization result;
  result.origin = origin;
  result.frame = frame;
  // Paper defaults: eigenvalues 2, −1, −1 (linear) or 1, 1, −2 (planar); the non-degenerate
  // eigenvector is the frame's z axis, the degenerate plane is spanned by its x and y axes.
  result.value = type == DegenerateType::Linear ? diagonal(-1, -1, 2) : diagonal(1, 1, -2);
  // Equation 3: Tx = diag(1, −1, 0), Ty = symmetric xy unit, Tz = 0 (wedge); a trisector
  // negates Ty. The 2-D pattern in the degenerate plane then has index +1/2 or −1/2.
  const double sign = pattern == DegeneratePattern::Wedge ? 1.0 : -1.0;
  result.jacobian[0] = diagonal(1, -1, 0);
  result.jacobian[1] = Tensor{0, 0, 0, sign, 0, 0};
  result.jacobian[2] = Tensor{};
  return result;
}

Mat3 rotationFromEulerDegrees(const Vec3& degrees) {
  if (!degrees.allFinite()) throw Error("rotation: Euler angles are not finite");
  const Vec3 r = degrees * (std::numbers::pi / 180.0);
  const Mat3 rx = Eigen::AngleAxisd(r.x(), Vec3::UnitX()).toRotationMatrix();
  const Mat3 ry = Eigen::AngleAxisd(r.y(), Vec3::UnitY()).toRotationMatrix();
  const Mat3 rz = Eigen::AngleAxisd(r.z(), Vec3::UnitZ()).toRotationMatrix();
  return rz * ry * rx;
}

}  // namespace tfd::core
