#pragma once
// Whole-file reads and atomic whole-file writes with error messages naming the file.
#include <filesystem>
#include <string>

namespace tfd::io {

/// Reads a whole file. Throws core::Error "cannot open file 'x': <reason>".
std::string readFileBytes(const std::filesystem::path& path);

/// Writes `bytes` to `path` atomically (io/atomic_file.h); throws core::Error naming the file.
void writeFileBytes(const std::filesystem::path& path, const std::string& bytes);

}  // namespace tfd::io
