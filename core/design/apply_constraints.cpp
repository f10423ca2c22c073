#include "core/design/apply_constraints.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/design/curve_constraint.h"
#include "core/error.h"
#include "core/linalg/parallel.h"
#include "core/point_locator.h"

namespace tfd::core {

namespace {

std::string describe(int index, const Vec3& p) {
  std::ostringstream out;
  out << "point element " << index << " at (" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

void applyLocatedPointElement(const TetMesh& mesh, const PointElement& element, int index,
                              const std::optional<TetLocation>& location,
                              FixedValueAccumulator& accumulator) {
  const Vec3& origin = element.field.origin;
  if (!origin.allFinite()) throw Error(describe(index, origin) + ": position is not finite");
  if (!std::isfinite(element.radius) || element.radius < 0)
    throw Error(describe(index, origin) + ": radius must be a number ≥ 0");
  if (!std::isfinite(element.radiusEdges) || element.radiusEdges < 0)
    throw Error(describe(index, origin) + ": radius in edge lengths must be a number ≥ 0");
  for (const Tensor& t : element.field.jacobian)
    for (double c : t.components())
      if (!std::isfinite(c)) throw Error(describe(index, origin) + ": Jacobian is not finite");
  for (double c : element.field.value.components())
    if (!std::isfinite(c)) throw Error(describe(index, origin) + ": tensor value is not finite");
  if (!location)
    throw Error(describe(index, origin) + " is outside the mesh (bounds " + [&] {
      std::ostringstream b;
      b << "(" << mesh.boundsMin().transpose() << ") to (" << mesh.boundsMax().transpose() << ")";
      return b.str();
    }() + ")");
  const double epsilon = kCurveBlendEpsilon * mesh.meanEdgeLength();
  const auto& pos = mesh.positions();
  std::vector<int> vertices(mesh.tets()[location->tet].begin(), mesh.tets()[location->tet].end());
  const double radius = std::max(element.radius, element.radiusEdges * mesh.meanEdgeLength());
  if (radius > 0) {
    // Every vertex within the radius (a parallel scan in fixed chunks keeps the order).
    const double r2 = radius * radius;
    const std::size_t n = mesh.vertexCount();
    const std::size_t chunks = (n + linalg::kChunk - 1) / linalg::kChunk;
    std::vector<std::vector<int>> found(chunks);
    linalg::parallelRanges(
        chunks,
        [&](std::size_t b, std::size_t e) {
          for (std::size_t c = b; c < e; ++c)
            for (std::size_t v = c * linalg::kChunk; v < std::min(n, (c + 1) * linalg::kChunk); ++v)
              if ((pos[v] - origin).squaredNorm() <= r2) found[c].push_back(static_cast<int>(v));
        },
        1);
    for (const auto& f : found) vertices.insert(vertices.end(), f.begin(), f.end());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (int v : vertices) {
    const double d = (pos[v] - origin).norm();
    accumulator.add(v, element.field.evaluate(pos[v]), blendWeight(d, epsilon));
  }
}

/// Where each point element's origin is (non-finite origins stay unlocated: the element's own
/// checks report them). A few points are found by one scan over the tets, so a first cook
/// does not pay for the mesh's point-location grid (core::locatePoints).
std::vector<std::optional<TetLocation>> locateOrigins(const TetMesh& mesh,
                                                      const std::vector<PointElement>& points) {
  std::vector<Vec3> origins;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].field.origin.allFinite()) continue;
    origins.push_back(points[i].field.origin);
    which.push_back(i);
  }
  const auto found = locatePoints(mesh, origins);
  std::vector<std::optional<TetLocation>> out(points.size());
  for (std::size_t k = 0; k < which.size(); ++k) out[which[k]] = found[k];
  return out;
}

}  // namespace

void applyPointElement(const TetMesh& mesh, const PointElement& element, int index,
                       FixedValueAccumulator& accumulator) {
  applyLocatedPointElement(mesh, element, index, locateOrigins(mesh, {element}).front(),
                           accumulator);
}

FixedValues applyConstraints(const TetMesh& mesh, const ConstraintSet& constraints) {
  FixedValueAccumulator accumulator(mesh.vertexCount());
  const auto locations = locateOrigins(mesh, constraints.points);
  for (std::size_t i = 0; i < constraints.points.size(); ++i)
    applyLocatedPointElement(mesh, constraints.points[i], static_cast<int>(i), locations[i],
                             accumulator);
  for (std::size_t i = 0; i < constraints.curves.size(); ++i) {
    try {
      applyCurveElement(mesh, constraints.curves[i], accumulator);
    } catch (const Cancelled&) {
      throw;
    } catch (const Error& e) {
      throw Error("curve element " + std::to_string(i) + ": " + e.what());
    }
  }
  FixedValues result = accumulator.finish();
  result.pointElements = constraints.points.size();
  result.curveElements = constraints.curves.size();
  return result;
}

}  // namespace tfd::core
