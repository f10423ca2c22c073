#pragma once
// Numbered file patterns of image sequences: `slice.%04d.exr`, `slice.####.exr`, `s_%d.exr`
// (printf-like or a run of `#`, zero-padded to the given width); `%%` is a literal percent.
#include <optional>
#include <string>

namespace tfd::io {

/// `pattern` with its frame placeholder replaced by `frame`. Throws core::Error naming the
/// pattern when it has no placeholder or more than one.
std::string expandFramePattern(const std::string& pattern, int frame);

/// True when the placeholder lies in the file name, not in a folder name (throws like
/// expandFramePattern for a bad pattern).
bool framePlaceholderInFileName(const std::string& pattern);

/// The frame number `fileName` stands for under the file-name part of `pattern`, when
/// expandFramePattern(pattern, n) would give exactly that name; nothing otherwise.
std::optional<int> frameOfFileName(const std::string& pattern, const std::string& fileName);

}  // namespace tfd::io
