#pragma once
// Which tet holds a point: a uniform grid over the tets' bounding boxes.
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

class TetMesh;

struct TetLocation {
  int tet = -1;
  Eigen::Vector4d barycentric = Eigen::Vector4d::Zero();  ///< weights of the tet's 4 vertices
};

/// Answers "which tet contains p" in O(1) expected time: each grid cell lists the tets whose
/// bounding boxes overlap it (about one tet per cell). Queries are const and thread-safe.
class PointLocator {
 public:
  explicit PointLocator(const TetMesh& mesh);

  /// The tet containing p (barycentric coordinates ≥ −tolerance), or nothing when p lies
  /// outside the mesh. On a shared face or edge the tet with the largest smallest barycentric
  /// coordinate wins, so the answer does not depend on traversal order.
  std::optional<TetLocation> locate(const Vec3& p, double tolerance = 1e-10) const;

  /// Locates many points in parallel; entry i is empty when points[i] is outside.
  std::vector<std::optional<TetLocation>> locateAll(const std::vector<Vec3>& points) const;

 private:
  std::array<int, 3> cellOf(const Vec3& p) const;

  const TetMesh& mesh_;
  Vec3 origin_;
  double cellSize_ = 1;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> cellStart_;
  std::vector<int> cellTets_;
};

}  // namespace tfd::core
