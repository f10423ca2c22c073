#pragma once
// What a side-effect node left on disk: each file it wrote, with its size and modification
// time right after the cook. A later cook of the same evaluator compares them with the disk
// to decide whether the node must run again although its cache key is unchanged.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace tfd::graph {

struct FileStamp {
  std::filesystem::path path;
  bool exists = false;
  std::uintmax_t size = 0;
  std::int64_t mtime = 0;  ///< last write time, in the file clock's ticks
  bool operator==(const FileStamp&) const = default;
};

/// The file's stamp now (exists = false when it is missing or not a regular file).
FileStamp stampFile(const std::filesystem::path& path);

/// True when every file still exists with the recorded size and modification time.
bool filesUnchanged(const std::vector<FileStamp>& files);

}  // namespace tfd::graph
