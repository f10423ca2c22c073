#pragma once
// What render/ draws, as plain arrays (built on the CPU from core values by scene_builder.h,
// uploaded by Renderer): a translucent boundary surface, an opaque cutting plane with
// per-vertex colours, wide lines (degenerate curves, constraint curves and frames, regions)
// thin traced lines (hyperstreamlines) and round points (transition points, design points, picks).
#include <array>
#include <cstdint>
#include <vector>

#include "render/camera.h"

namespace tfd::render {

using Rgba = std::array<std::uint8_t, 4>;

struct Surface {
  std::vector<float> positions;  ///< xyz per vertex
  std::vector<float> normals;    ///< xyz per vertex
  std::vector<std::uint32_t> indices;
  std::array<float, 4> colour{0.72f, 0.76f, 0.84f, 0.22f};
};

struct ColouredTriangles {
  std::vector<float> positions;  ///< xyz per vertex, three vertices per triangle
  std::vector<Rgba> colours;     ///< per vertex
};

struct LineSet {
  std::vector<float> positions;  ///< xyz per vertex, two vertices per segment
  std::vector<Rgba> colours;     ///< per vertex
  float width = 3;               ///< pixels
  void add(const Vec3& a, const Vec3& b, Rgba ca, Rgba cb);
  std::size_t segmentCount() const { return positions.size() / 6; }
};

struct PointSet {
  std::vector<float> positions;
  std::vector<Rgba> colours;
  float size = 8;  ///< pixels
  void add(const Vec3& p, Rgba c);
};

struct Scene {
  Surface boundary;
  ColouredTriangles slice;
  LineSet curves;               ///< degenerate curves (pickable)
  LineSet overlay;              ///< constraint curves, frames, regions
  LineSet lines{{}, {}, 1.5f};  ///< traced lines (hyperstreamlines), thin
  PointSet points;              ///< transition points, design points
  PointSet markers;             ///< picks and other highlights (drawn on top)
  Bounds bounds;
  bool empty() const {
    return boundary.indices.empty() && slice.positions.empty() && curves.positions.empty() &&
           overlay.positions.empty() && lines.positions.empty() && points.positions.empty();
  }
};

}  // namespace tfd::render
