#include "core/tensor_field.h"

#include "core/error.h"
#include "core/point_locator.h"

namespace tfd::core {

TensorField::TensorField(std::shared_ptr<const TetMesh> mesh, std::vector<Tensor> values)
    : mesh_(std::move(mesh)), values_(std::move(values)) {
  if (!mesh_) throw Error("tensor field without a mesh");
  if (values_.size() != mesh_->vertexCount()) {
    throw Error("tensor field has " + std::to_string(values_.size()) + " values for " +
                std::to_string(mesh_->vertexCount()) + " mesh vertices");
  }
}

Tensor TensorField::interpolate(int tet, const Eigen::Vector4d& b) const {
  const auto& k = mesh_->tets()[tet];
  return values_[k[0]] * b[0] + values_[k[1]] * b[1] + values_[k[2]] * b[2] +
         values_[k[3]] * b[3];
}

std::optional<Tensor> TensorField::sample(const Vec3& p) const {
  const auto location = mesh_->locator().locate(p);
  if (!location) return {};
  return interpolate(location->tet, location->barycentric);
}

}  // namespace tfd::core
