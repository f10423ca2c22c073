#pragma once
// What an OpenVDB file announces before its trees (header, file metadata, grid descriptors,
// each grid's metadata), checked against the bytes the file has, before OpenVDB reads it.
// OpenVDB allocates a string of whatever length a file announces and copies it into its
// messages: a damaged 734-byte file announcing a 150 MB grid type kept `tfd info` busy for
// 9 s. Layout of file versions 222-224 (OpenVDB 7-10, io/Archive.cc, io/GridDescriptor.cc);
// OpenVDB reads files of later versions with the same layout, and so are they checked.
#include <cstdint>
#include <filesystem>

namespace tfd::io {

struct VdbLayout {
  bool magic = false;         ///< starts as an OpenVDB file does (otherwise OpenVDB says so)
  std::uint32_t version = 0;  ///< file format version
  bool gridOffsets = false;   ///< grid descriptors say where each grid is (files, not streams)
  /// Everything before the trees was checked: a version from 222 on, with grid offsets.
  bool checked = false;
};

/// Throws core::Error naming the file and the part whose announced size exceeds what is left.
/// Files of older versions, or without grid offsets, are checked as far as their layout is
/// known (the header and file metadata) and left to OpenVDB beyond that (`checked` false).
VdbLayout checkVdbLayout(const std::filesystem::path& path);

}  // namespace tfd::io
