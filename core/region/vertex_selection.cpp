#include "core/region/vertex_selection.h"

#include "core/region/curve_tube.h"

namespace tfd::core {

std::vector<int> verticesInSphere(const TetMesh& mesh, const Vec3& center, double radius) {
  const auto& pos = mesh.positions();
  const double r2 = radius * radius;
  std::vector<int> region;
  for (int v = 0; v < static_cast<int>(pos.size()); ++v)
    if ((pos[v] - center).squaredNorm() <= r2) region.push_back(v);
  return region;
}

std::vector<int> verticesInBox(const TetMesh& mesh, const Vec3& center, const Vec3& size) {
  const auto& pos = mesh.positions();
  const Vec3 half = 0.5 * size;
  std::vector<int> region;
  for (int v = 0; v < static_cast<int>(pos.size()); ++v)
    if (((pos[v] - center).cwiseAbs() - half).maxCoeff() <= 0) region.push_back(v);
  return region;
}

std::vector<int> verticesAroundCurve(const TetMesh& mesh, const DegenerateCurve& curve,
                                     double radius) {
  std::vector<Vec3> polyline = curve.points;
  const bool closed = curve.closed && polyline.size() >= 3;
  if (polyline.size() == 1) polyline.push_back(polyline.front());  // a ball around one point
  const TubeQuery tube = findTubeVertices(mesh, polyline, closed, radius);
  std::vector<int> region;
  region.reserve(tube.vertices.size());
  for (const TubeVertex& v : tube.vertices) region.push_back(v.vertex);
  return region;
}

}  // namespace tfd::core
