#pragma once
// Whole-file text writes that never leave a partial file: write a temporary file next to the
// target, then rename it over the target. (The graph layer may not use io/atomic_file.h.)
#include <filesystem>
#include <string_view>

namespace tfd::graph {

/// Throws GraphError("cannot write <path>: <reason>") on failure; the target is then untouched.
void writeTextFileAtomically(const std::filesystem::path& path, std::string_view content);

}  // namespace tfd::graph
