#pragma once
// Reads an OpenVDB file into plain data, for inspection (`tfd info`) and for tests that check
// what the VDB writer produced. Only the OpenVDB library reads the file.
//
// Trees of untrusted files are never read: OpenVDB 10.0 (Debian) copies an uncompressed chunk of
// the size the file announces into the node's buffer before comparing that size with the
// buffer's (io::bloscFromStream and io::zipFromStream), so a damaged tree writes past a heap
// buffer (found by fuzz_info_vdb). `tfd info` reads what `vdb_print -l` reads: readVdbMetadata.
#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/tensor.h"

namespace tfd::io {

struct VdbGridData {
  std::string name;
  std::string valueType;   ///< OpenVDB's name: "float", "vec3s", …
  std::string gridClass;   ///< "unknown", "level set", "fog volume", "staggered"
  std::string vectorType;  ///< "invariant", "covariant", … (meaningful for vector grids)
  bool saveFloatAsHalf = false;
  /// Every grid metadata entry as text (OpenVDB's Metadata::str()), including the standard
  /// ones (name, class, file_bbox_min, …) and the writer's own.
  std::map<std::string, std::string> metadata;
  bool linearTransform = false;
  core::Vec3 voxelSize = core::Vec3::Zero();    ///< transform's voxel size per axis
  core::Vec3 indexOrigin = core::Vec3::Zero();  ///< world position of index (0, 0, 0)
  std::size_t activeVoxelCount = 0;
  /// False when only metadata was read and the writer recorded no statistics.
  bool activeVoxelsKnown = true;
  std::array<int, 3> activeMin{0, 0, 0}, activeMax{-1, -1, -1};  ///< active voxel bounds

  /// Filled for float, double, Vec3s, Vec3d and int32 grids when values were asked for:
  /// one entry per active voxel (tiles expanded), in the tree's iteration order; scalars use
  /// value[0] only.
  struct Voxel {
    std::array<int, 3> ijk;
    std::array<double, 3> value;
  };
  std::vector<Voxel> activeVoxels;
  std::array<double, 3> background{0, 0, 0};
  /// Inactive voxels stored in leaf nodes whose value is not the background.
  std::size_t inactiveNonBackground = 0;
  bool valuesLoaded = false;
};

struct VdbFileData {
  std::map<std::string, std::string> fileMetadata;  ///< as text
  std::vector<VdbGridData> grids;                   ///< in file order
};

/// The file's and each grid's metadata and transform, never the trees; the active voxel count
/// and bounds are the statistics the writer recorded; grids in name order (OpenVDB's grid
/// descriptors), not file order. Safe on any file. Throws core::Error
/// naming the file when it cannot be opened or read.
VdbFileData readVdbMetadata(const std::filesystem::path& path);

/// Everything, trees included: only for files tfd wrote (tests), see above. Throws core::Error
/// naming the file when it cannot be opened or read.
VdbFileData readVdbFile(const std::filesystem::path& path, bool loadValues = true);

}  // namespace tfd::io
