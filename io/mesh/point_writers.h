#pragma once
// Instance points (core/synth/instance_points.h) to PLY, for instancing in Houdini or Blender.
#include <filesystem>

#include "core/synth/instance_points.h"
#include "io/mesh/surface_writers.h"

namespace tfd::io {

/// A PLY file with one `vertex` element per instance and no faces. Properties, in order:
/// `double x y z` (the position), `float orient_x orient_y orient_z orient_w` (the unit
/// quaternion turning the element's local axes to the world, in Houdini's `orient` order:
/// imaginary part first, real part last), `float pscale` (Houdini's uniform scale: the largest
/// of the instance's scales), `float scale_x scale_y scale_z` (per local axis) and `uchar kind`
/// (0 line element, 1 box element). Written atomically; throws core::Error naming the file.
void writeInstancePointsPly(const std::filesystem::path& path, const core::InstancePoints& points,
                            PlyEncoding encoding = PlyEncoding::BinaryLittleEndian);

}  // namespace tfd::io
