#pragma once
// Export of a TensorField to a sequence of OpenEXR images, one per z-slice of a voxel grid
// (EXR has no 3D volume convention; compositors read numbered sequences).
//
// Files: the caller's path pattern with one frame placeholder, either printf-like (`%d`,
// `%04d`: zero-padded to the given width) or a run of `#` (`####`: zero-padded to the run's
// length). Slice s = 0 … n−1 (bottom to top, z ascending) gets frame number firstFrame + s.
// A literal percent sign is written `%%`.
//
// Pixels: slice s is the z = const plane through voxel centres of index k = lattice.min.z + s
// (field_resample.h). Pixel (column c, row r) is voxel (i, j) = (min.x + c, max.y − r): row 0
// is the top of the image, at the largest y, so a viewer shows the slice as seen from +z with
// y up. Its world centre is firstPixel + c·columnStep + r·rowStep (header attributes below).
//
// Channels, 32-bit float (EXR sorts channels by name: select them by name):
//   T.xx T.yy T.zz T.xy T.yz T.xz   quantity "tensor" (VTK order; "T" is the tensor name)
//   T.eigval.x/.y/.z                "eigenvalues" λ1 ≥ λ2 ≥ λ3
//   T.e1.x/.y/.z, T.e2.…, T.e3.…    "eigenvectors" (unit, sign arbitrary)
//   density                         "density"
//   R G B                           preview (optional): a scalar of the field (e.g. closeness
//                                   to degeneracy, io/volume/voxel_density.h) through
//                                   previewColour, so a plain viewer shows the slice
//   A                               mask: 1 where the voxel centre is inside the mesh (optional)
// Pixels outside the mesh are 0 in every channel. Names follow OpenEXR's layer convention
// (ImfChannelList: the text before the last '.' is the layer): `T.xx` is channel `xx` of layer
// `T`, `T.eigval.x` channel `x` of layer `T.eigval`; R, G, B, A are the default layer, what a
// viewer shows.
// A ScalarVolume (writeVolumeExrSlices) is written on its own grid as R, G, B (the value, so
// any viewer shows it as grey levels) and A (its mask), 0 outside the mask.
//
// Slices: every z-slice, or with sliceCount = n > 0 only n evenly spaced ones (offsets
// s = ⌊(m + ½) N / n⌋, m = 0 … n−1, of the N slices), numbered by s as if all were written.
//
// Header attributes (besides the standard ones; compression ZIP, lossless):
//   tfd.voxelSize (double), tfd.origin (v3d, world centre of voxel index (0,0,0)),
//   tfd.indexMin / tfd.indexMax (v3i, the lattice's index box), tfd.axis (string "z"),
//   tfd.sliceIndex (int, voxel index k), tfd.frame (int), tfd.sliceCount (int),
//   tfd.z (double, world z of the slice), tfd.firstPixel (v3d), tfd.columnStep (v3d, +x·h),
//   tfd.rowStep (v3d, −y·h), tfd.tensorComponents (string "xx,yy,zz,xy,yz,xz"; fields only),
//   tfd.generator, tfd.source (strings; source only when given).
//
// Atomicity: every slice is first written to a hidden temporary beside its target
// (io::StagedFile, checked for completeness); only when all slices are written are they
// renamed into place. If any slice fails or the export is cancelled, the temporaries and any
// slice already renamed are removed, so no new slice file is left.
// Ownership: when the placeholder is in the file name, the exporter owns the files of its
// pattern in that folder: after a successful export, slices of the pattern that this export
// did not write (an earlier export with more slices or other frame numbers) are removed, and
// temporaries of the pattern left by a killed process are removed before writing.
#include <filesystem>
#include <string>

#include "core/progress.h"
#include "core/scalar_volume.h"
#include "core/tensor_field.h"
#include "io/volume/field_resample.h"
#include "io/volume/frame_pattern.h"
#include "io/volume/vdb_writer.h"
#include "io/volume/voxel_quantities.h"

namespace tfd::io {

struct ExrExportOptions {
  double voxelSize = 0;                    ///< world units per voxel; must be > 0
  core::Vec3 origin = core::Vec3::Zero();  ///< world position of voxel (0, 0, 0)'s centre
  VoxelQuantities quantities;              ///< default: the tensor only
  std::string tensorName = "T";
  bool mask = true;  ///< add the channel "A" (1 inside, 0 outside)
  /// When set, add R, G, B: previewColour of this scalar (expected in [0, 1]) inside the mesh.
  VoxelScalarFunction preview;
  int firstFrame = 0;  ///< frame number of the lowest slice
  int sliceCount = 0;  ///< 0: every slice; n > 0: n evenly spaced slices
  double maxVoxels = kDefaultMaxVoxels;
  std::string generator = "tfd";
  std::string source;
};

/// Writes one EXR file per z-slice (see above). Throws core::Error for a bad pattern or voxel
/// size, a grid above maxVoxels, no quantity selected, or a slice that cannot be written
/// (naming the file); core::Cancelled when cancelled. Slices are computed in parallel over
/// rows, each pixel on its own: files are identical for any thread count.
VoxelExportStats writeFieldExrSlices(const std::string& pattern, const core::TensorField& field,
                                     const ExrExportOptions& options,
                                     const core::Progress& progress = core::Progress());

struct VolumeExrOptions {
  int firstFrame = 0;  ///< frame number of the lowest slice
  int sliceCount = 0;  ///< 0: every slice; n > 0: n evenly spaced slices
  std::string generator = "tfd";
  std::string source;
};

/// Writes the volume's z-slices (see above: R, G, B the value, A the mask), with the same
/// header attributes, atomicity and ownership of the pattern's files as writeFieldExrSlices.
/// Throws core::Error for a bad pattern, an empty volume or arrays that do not match its grid,
/// or a slice that cannot be written; core::Cancelled when cancelled.
VoxelExportStats writeVolumeExrSlices(const std::string& pattern, const core::ScalarVolume& volume,
                                      const VolumeExrOptions& options,
                                      const core::Progress& progress = core::Progress());

}  // namespace tfd::io
