#pragma once
// Export of a TensorField to an OpenVDB file (.vdb), resampled on a regular voxel grid.
//
// Grids (names use the tensor name, "T" by default; OpenVDB 10 has no matrix grid type, so the
// symmetric tensor is split Houdini-style):
//   T.xx T.yy T.zz T.xy T.yz T.xz  FloatGrid, one per component (quantity "tensor")
//   T.eigval                       Vec3SGrid (λ1, λ2, λ3) descending ("eigenvalues")
//   T.e1 T.e2 T.e3                 Vec3SGrid, unit eigenvectors of λ1, λ2, λ3 ("eigenvectors");
//                                  vector type "invariant", their sign is arbitrary
//   density                        FloatGrid ("density", e.g. io/volume/voxel_density.h)
// Grid classes: the tensor-derived grids are "unknown" (no OpenVDB class fits a tensor
// component or an eigenvector); `density` is a fog volume (Blender's volume object and Houdini
// render it as imported) when none of its active values is negative, else unknown. Nothing is
// a level set: no grid is a signed distance.
// Every grid: background 0, linear transform with the voxel size, voxel (i, j, k) centred on
// world = origin + voxelSize * (i, j, k) (field_resample.h); active exactly at the voxels whose
// centre is inside the mesh, inactive (value 0) elsewhere; values stored as 32-bit floats.
// Grid metadata: tensor_components = "xx,yy,zz,xy,yz,xz" (all tensor-derived grids),
// component ("xx", …) on the six tensor grids. File metadata: generator, source (when given),
// tensor_components, voxel_convention.
//
// Sampling runs in parallel over 8³ leaf blocks aligned with OpenVDB's leaf nodes; each block
// builds its own leaves and the leaves are inserted serially in block order, so the file's
// grids are identical for any thread count. The file is written atomically (io::writeAtomically).
#include <filesystem>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scalar_volume.h"
#include "core/tensor_field.h"
#include "io/volume/field_resample.h"
#include "io/volume/voxel_quantities.h"

namespace tfd::io {

struct VdbExportOptions {
  double voxelSize = 0;                    ///< world units per voxel; must be > 0
  core::Vec3 origin = core::Vec3::Zero();  ///< world position of voxel (0, 0, 0)'s centre
  VoxelQuantities quantities;              ///< default: the tensor only
  std::string tensorName = "T";
  double maxVoxels = kDefaultMaxVoxels;  ///< refuse larger grids (counted over the mesh bounds)
  std::string generator = "tfd";         ///< file metadata "generator"
  std::string source;                    ///< file metadata "source" (e.g. graph and node)
};

/// What a voxel export produced.
struct VoxelExportStats {
  VoxelLattice lattice;          ///< the index box sampled (the mesh's bounds)
  std::size_t activeVoxels = 0;  ///< voxels whose centre is inside the mesh
  int filesWritten = 0;
  std::vector<std::filesystem::path> files;  ///< the files written, in order (EXR: by slice)
};

/// Writes the selected grids of `field` to `path`. Throws core::Error for a bad voxel size, a
/// grid above maxVoxels, no quantity selected, or a file that cannot be written (naming it);
/// core::Cancelled when `progress` is cancelled. On any error no partial file is left and an
/// existing file at `path` stays untouched.
VoxelExportStats writeFieldVdb(const std::filesystem::path& path, const core::TensorField& field,
                               const VdbExportOptions& options,
                               const core::Progress& progress = core::Progress());

struct VolumeVdbOptions {
  std::string gridName = "density";
  std::string generator = "tfd";  ///< file metadata "generator"
  std::string source;             ///< file metadata "source" (e.g. graph and node)
};

/// Writes a scalar volume as one FloatGrid named `gridName` (default "density"), grid class
/// fog volume when no value in the mask is negative (Houdini and Blender render it with no
/// set-up), else unknown: background 0, active exactly at
/// the voxels of the volume's mask, same transform and voxel convention as writeFieldVdb
/// (voxel (i, j, k) of the volume's grid is index coordinate (i, j, k)), 32-bit floats. File
/// metadata: generator, source (when given), voxel_convention. Leaves are built in parallel
/// and inserted in block order (identical files for any thread count); written atomically.
/// Throws core::Error for an empty volume, arrays that do not match its grid, or a file that
/// cannot be written (naming it); core::Cancelled when cancelled.
VoxelExportStats writeVolumeVdb(const std::filesystem::path& path, const core::ScalarVolume& volume,
                                const VolumeVdbOptions& options,
                                const core::Progress& progress = core::Progress());

}  // namespace tfd::io
