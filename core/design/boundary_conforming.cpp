#include "core/design/boundary_conforming.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace tfd::core {

Tensor conformToNormal(const Tensor& t, const Vec3& normal) {
  const double length = normal.norm();
  if (!(length > 0) || !std::isfinite(length)) return t;
  const Vec3 n = normal / length;
  const Mat3 m = t.matrix();
  const Mat3 p = Mat3::Identity() - n * n.transpose();
  // Equation 4 with M_BN = 0: keep the tangent block M_B and the normal entry M_N.
  return Tensor::fromMatrix(p * m * p + n.dot(m * n) * (n * n.transpose()));
}

std::vector<Tensor> conformingBoundaryValues(const TetMesh& mesh,
                                             const std::vector<Tensor>& values) {
  if (values.size() != mesh.vertexCount())
    throw Error("boundary-conforming values: expected one tensor per vertex (" +
                std::to_string(mesh.vertexCount()) + "), got " + std::to_string(values.size()));
  const auto& boundary = mesh.boundaryVertices();
  std::vector<Tensor> out(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i)
    out[i] = conformToNormal(values[boundary[i]], mesh.vertexNormals()[boundary[i]]);
  return out;
}

}  // namespace tfd::core
