#pragma once
// Oriented boxes and their exact overlap test, for rejecting colliding elements (paper §8.2;
// algorithms note §9.2 step 5).
#include "core/tensor.h"

namespace tfd::core {

/// A box centred at `centre` whose local axis i is `axes.col(i)` (orthonormal columns) with
/// half-length `half[i]` along it.
struct OrientedBox {
  Vec3 centre = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
  Vec3 half = Vec3::Zero();

  /// Radius of the sphere around the centre that holds the box.
  double boundingRadius() const { return half.norm(); }
};

/// True when the two closed boxes share a point. Separating-axis test over the 15 candidate
/// axes (3 face normals of each box, 9 edge-edge cross products; Gottschalk et al. 1996): two
/// convex polytopes are disjoint exactly when one of these axes separates them. The edge-edge
/// axes of (nearly) parallel edges vanish; a relative 1e-12 guard on the rotation terms keeps
/// them from ever separating boxes that touch (the face axes decide those cases).
bool boxesOverlap(const OrientedBox& a, const OrientedBox& b);

}  // namespace tfd::core
