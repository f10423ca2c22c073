#pragma once
// Twist-free (rotation-minimising, Bishop) frames along a polyline, by the double reflection
// method of Wang, Jüttler, Zheng & Liu (2008): the frame at point i+1 is the frame at i
// reflected in the plane normal to the chord, then in the plane normal to the difference of
// the tangents. It matches discrete parallel transport (algorithms note §10) to high order, so
// tubes swept with it do not twist about their axis.
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

struct Frame {
  Vec3 tangent;   ///< unit, along the line
  Vec3 normal;    ///< unit, perpendicular to the tangent
  Vec3 binormal;  ///< tangent × normal
};

/// Unit tangent per point: the normalised sum of the unit chords on either side (one-sided at
/// the ends). Zero-length chords are skipped.
std::vector<Vec3> polylineTangents(const std::vector<Vec3>& points);

/// One frame per point. The first normal is a fixed perpendicular of the first tangent; a
/// polyline with fewer than two distinct points gets the world axes.
std::vector<Frame> bishopFrames(const std::vector<Vec3>& points);

/// A unit vector perpendicular to unit t, chosen deterministically.
Vec3 anyPerpendicular(const Vec3& t);

}  // namespace tfd::core
