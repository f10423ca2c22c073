#pragma once
// Instance points: where copies of an element go, how they are turned and scaled. What
// `ElementSynthesis` outputs beside its mesh, so users can instance their own geometry
// (Houdini's `orient` quaternion and `pscale`, Blender's instance rotation and scale).
#include <cstdint>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// Which built-in or user element an instance stands for.
enum class ElementKind : std::uint8_t {
  Line,  ///< a stick along the major eigenvector (linear regions)
  Box,   ///< a leaf normal to the minor eigenvector (planar regions)
};

/// One instance: its centre, the rotation taking the element's local x, y, z axes to its world
/// axes as a unit quaternion (w, x, y, z), and a scale per local axis.
struct InstancePoint {
  Vec3 position = Vec3::Zero();
  Eigen::Vector4d orient{1, 0, 0, 0};  ///< (w, x, y, z), unit length
  Vec3 scale = Vec3::Ones();           ///< per local axis; `pscale` is their maximum
  ElementKind kind = ElementKind::Line;
};

struct InstancePoints {
  std::vector<InstancePoint> points;
};

}  // namespace tfd::core
