#pragma once
// Picking in the viewport, generic over node types (read from the declarations by name):
// - a point-list parameter `picks`: a click on a degenerate curve appends the point;
// - a point parameter `pick`: a click on a degenerate curve sets it;
// - a point-list parameter `points` hinted as positions (CurveConstraint's control points):
//   a click in space appends a point on the plane through the last point (or the view's
//   target) facing the camera.
// Each click is one undo step (GraphDocument::setParam). The geometry is plain maths on the
// camera and the scene's curve segments, testable without OpenGL.
#include <optional>
#include <string>
#include <vector>

#include "graph/graph.h"
#include "render/camera.h"
#include "render/scene.h"

namespace tfd::ui {

class GraphDocument;

struct PickTarget {
  enum class Kind { None, CurvePoints, CurvePoint, SpacePoints };
  Kind kind = Kind::None;
  std::string node, param;
  bool needsCurve() const { return kind == Kind::CurvePoints || kind == Kind::CurvePoint; }
};

/// What a click does for this node (picks, then pick, then points).
PickTarget pickTargetFor(const graph::Node& node);

/// The points the node's pick parameters hold (for markers): picks, pick (when a target),
/// position-hinted points.
std::vector<render::Vec3> pickedPoints(const graph::Node& node);

/// The point on the scene's degenerate curves nearest the pixel (x right, y down), when a
/// segment passes within `tolerance` pixels; among several, the nearest to the eye.
std::optional<render::Vec3> pickCurvePoint(const render::LineSet& curves,
                                           const render::Camera& camera, int width, int height,
                                           double px, double py, double tolerance = 8);

/// The point under the pixel on the plane through `anchor` facing the camera.
render::Vec3 pointInSpace(const render::Camera& camera, int width, int height, double px, double py,
                          const render::Vec3& anchor);

/// The parameter value after adding (or, for `pick`, setting) `p`, rounded to 1e-4.
graph::ParamValue pickedValue(const graph::Node& node, const PickTarget& target,
                              const render::Vec3& p);

/// Applies a click as one undo step; false (with the document's lastError) when refused.
bool applyPick(GraphDocument& document, const PickTarget& target, const render::Vec3& p);

}  // namespace tfd::ui
