#pragma once
// Which per-voxel quantities a voxel export (OpenVDB, OpenEXR) writes, and their values at one
// sampled voxel. Every quantity is derived from the tensor interpolated at the voxel centre
// (eigenvalues of the interpolated tensor, not interpolated eigenvalues).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/tensor.h"
#include "core/tet_mesh.h"
#include "io/volume/field_resample.h"

namespace tfd::io {

/// A scalar at a voxel centre inside the mesh, e.g. a noise density. Called concurrently from
/// worker threads: it must be thread-safe and give the same value for the same input.
using VoxelScalarFunction =
    std::function<double(const core::Vec3& position, const VoxelSample& sample)>;

/// A VoxelScalarFunction that interpolates one value per mesh vertex linearly inside each tet.
/// Throws core::Error when the count does not match the mesh.
VoxelScalarFunction interpolateVertexScalars(std::shared_ptr<const core::TetMesh> mesh,
                                             std::vector<double> values);

struct VoxelQuantities {
  bool tensor = true;         ///< six components, VTK order xx, yy, zz, xy, yz, xz
  bool eigenvalues = false;   ///< λ1 ≥ λ2 ≥ λ3 of the sampled tensor (core::eigenDecompose)
  bool eigenvectors = false;  ///< unit e1, e2, e3; their sign is arbitrary (line fields)
  VoxelScalarFunction density;  ///< written as a scalar "density" when set

  /// Number of floats evaluate() writes: 6 + 3 + 9 + 1 for everything.
  int channelCount() const;
  /// Channel names in evaluate() order, given the tensor's name (e.g. "T"):
  /// T.xx T.yy T.zz T.xy T.yz T.xz, T.eigval.x/y/z, T.e1.x/y/z, T.e2.…, T.e3.…, density.
  std::vector<std::string> channelNames(const std::string& tensorName) const;
  /// Writes channelCount() floats for an inside voxel (the caller writes zeros outside).
  void evaluate(const core::Vec3& position, const VoxelSample& sample, float* out) const;
};

}  // namespace tfd::io
