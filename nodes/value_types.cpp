#include "nodes/value_types.h"

namespace tfd::nodes::detail {

std::size_t meshBytes(const core::TetMesh& mesh) {
  // Positions, tets and the derived topology: about 200 bytes per tet in all.
  return mesh.vertexCount() * 64 + mesh.tetCount() * 200;
}

std::size_t fieldBytes(const core::TensorField& field) {
  // The mesh is shared and accounted for by its own node.
  return field.values().size() * sizeof(core::Tensor);
}

std::size_t constraintBytes(const core::ConstraintSet& set) {
  std::size_t bytes = set.points.size() * sizeof(core::PointElement);
  for (const auto& curve : set.curves) {
    bytes += curve.samples.size() * sizeof(core::LocalLinearization);
  }
  return bytes;
}

std::size_t curvesBytes(const core::DegenerateCurves& curves) { return curves.byteSize(); }

std::size_t surfaceMeshBytes(const core::SurfaceMesh& mesh) {
  return mesh.positions.size() * sizeof(core::Vec3) +
         mesh.triangles.size() * sizeof(mesh.triangles[0]);
}

std::size_t instancePointsBytes(const core::InstancePoints& points) {
  return points.points.size() * sizeof(core::InstancePoint);
}

std::size_t volumeBytes(const core::ScalarVolume& volume) {
  return volume.values.size() * sizeof(float) + volume.mask.size();
}
std::size_t linesBytes(const core::Polylines& lines) { return lines.byteSize(); }
std::size_t regionBytes(const core::TetRegion& region) { return region.byteSize(); }

}  // namespace tfd::nodes::detail
