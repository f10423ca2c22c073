#pragma once
// Writers never leave a partial file: they write to a temporary file beside the target and
// rename it into place only when everything was written.
#include <filesystem>
#include <functional>

namespace tfd::io {

/// Calls `write(tempPath)` and then renames tempPath to `path`. On any exception the temporary
/// file is removed and the exception propagates; an existing file at `path` stays untouched.
/// Creates missing parent folders. Throws core::Error naming the file when the folder cannot be
/// created or the rename fails.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& tempPath)>& write);

}  // namespace tfd::io
