#pragma once
// One tensor per vertex of a shared TetMesh, linearly interpolated inside each tet (paper §4).
#include <memory>
#include <optional>
#include <vector>

#include "core/tensor.h"
#include "core/tet_mesh.h"

namespace tfd::core {

/// Immutable value: edit operations return a new field that shares the same mesh.
class TensorField {
 public:
  /// Throws core::Error when there is not exactly one value per vertex.
  TensorField(std::shared_ptr<const TetMesh> mesh, std::vector<Tensor> values);

  const TetMesh& mesh() const { return *mesh_; }
  const std::shared_ptr<const TetMesh>& meshPtr() const { return mesh_; }
  const std::vector<Tensor>& values() const { return values_; }
  const Tensor& at(int vertex) const { return values_[vertex]; }

  /// Barycentric interpolation inside tet t.
  Tensor interpolate(int tet, const Eigen::Vector4d& barycentric) const;
  /// The field at p, or nothing when p is outside the mesh.
  std::optional<Tensor> sample(const Vec3& p) const;

 private:
  std::shared_ptr<const TetMesh> mesh_;
  std::vector<Tensor> values_;
};

}  // namespace tfd::core
