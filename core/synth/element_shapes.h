#pragma once
// The geometry instanced by element synthesis: built-in sticks and leaves (paper Fig. 2), or a
// user's meshes, each normalised to a unit-size local frame.
#include "core/surface/surface_mesh.h"
#include "core/synth/instance_points.h"

namespace tfd::core {

/// An element in its local frame: centred on its bounding box, longest side 1. The frame's
/// x axis is the element's long axis (a stick's length, a leaf's midrib), z a leaf's normal.
/// `half` holds the bounding box's half-sides: the oriented box used for collisions.
struct ElementShape {
  SurfaceMesh mesh;
  Vec3 half = Vec3::Zero();
};

/// Recentres `mesh` on its bounding box and scales it so its longest side is 1. Throws
/// core::Error naming `what` for a mesh with no triangles or a zero-size bounding box.
ElementShape normalizedElement(const SurfaceMesh& mesh, const char* what);

/// A wooden stick: an octagonal prism of length 1 along x, diameter 0.09, closed at both ends.
ElementShape builtinStick();
/// A leaf: a closed thin lens in the xy plane (length 1 along x, width 0.45 along y, at most
/// 0.04 thick along z), symmetric under the half-turns about x, y and z (box symmetry).
ElementShape builtinLeaf();

/// The shapes instanced for each element kind.
struct ElementShapes {
  ElementShape line = builtinStick();
  ElementShape box = builtinLeaf();
  const ElementShape& of(ElementKind kind) const { return kind == ElementKind::Line ? line : box; }
};

}  // namespace tfd::core
