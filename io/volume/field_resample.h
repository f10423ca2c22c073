#pragma once
// Sampling a TensorField at the centres of a regular voxel lattice, the common first step of
// the OpenVDB and OpenEXR exports.
//
// Voxel convention (shared by every voxel export of tfd): voxel (i, j, k) is the cube of side
// `voxelSize` centred on
//     world = origin + voxelSize * (i, j, k),
// so voxel centres sit on integer index coordinates, as in OpenVDB's linear transforms. With the
// default origin 0, centres are the integer multiples of the voxel size. A voxel is inside the
// volume (active) when its centre lies in a tet of the mesh (PointLocator's tolerance); its value
// is the field's linear interpolation there (paper §4). Voxels outside hold 0.
#include <array>
#include <cstddef>
#include <vector>

#include "core/point_locator.h"
#include "core/progress.h"
#include "core/tensor.h"
#include "core/tensor_field.h"
#include "core/voxel_grid.h"

namespace tfd::io {

/// Voxel counts above this are refused unless the caller raises the limit (2e8 voxels of one
/// float each is already 800 MB per grid).
inline constexpr double kDefaultMaxVoxels = 2e8;

/// A box of voxel indices [min, max] (inclusive) on the lattice described above (the same
/// convention as core::VoxelGrid, which it is).
using VoxelLattice = core::VoxelGrid;

/// The smallest index box holding every voxel centre inside the mesh's bounding box.
/// Throws core::Error when voxelSize is not a finite positive number, when origin is not
/// finite, when no voxel centre falls inside the bounds (voxel size much larger than the mesh)
/// or when the box has more than maxVoxels voxels; the messages name the voxel size.
VoxelLattice latticeForMesh(const core::TetMesh& mesh, double voxelSize,
                            const core::Vec3& origin = core::Vec3::Zero(),
                            double maxVoxels = kDefaultMaxVoxels);

/// The field at one voxel centre: where it fell and the interpolated tensor.
struct VoxelSample {
  int tet = -1;  ///< −1 when the centre is outside the mesh
  Eigen::Vector4d barycentric = Eigen::Vector4d::Zero();
  core::Tensor value;  ///< zero outside
  bool inside() const { return tet >= 0; }
};

/// Samples `field` at one point (outside: tet −1 and a zero tensor).
VoxelSample sampleField(const core::TensorField& field, const core::Vec3& position);

/// Samples a sequence of nearby points (a row of voxels) faster than sampleField, with exactly
/// sampleField's results: it walks from the previous point's tet across faces (a few steps)
/// and accepts a tet only when the point is strictly inside it (smallest barycentric
/// coordinate > 1e-9), where the point locator could not answer otherwise; any other case
/// falls back to the locator. Holds state: use one per task, not across threads.
class RowSampler {
 public:
  explicit RowSampler(const core::TensorField& field) : field_(field) {}
  VoxelSample operator()(const core::Vec3& position);

 private:
  const core::TensorField& field_;
  int lastTet_ = -1;
};

/// Samples the field at every voxel centre of the index box [lo, hi] (inclusive), ordered
/// x fastest, then y, then z. Rows run in parallel, each with its own RowSampler, and every
/// voxel equals sampleField at its centre, so the result is bitwise identical for any thread
/// count. Throws core::Cancelled when `progress`
/// is cancelled (checked per row on the worker threads).
std::vector<VoxelSample> sampleVoxels(const core::TensorField& field, const VoxelLattice& lattice,
                                      const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                                      const core::Progress& progress = core::Progress());

}  // namespace tfd::io
