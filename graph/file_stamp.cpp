#include "graph/file_stamp.h"

#include <system_error>

namespace tfd::graph {

FileStamp stampFile(const std::filesystem::path& path) {
  FileStamp s;
  s.path = path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || ec) return s;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return s;
  const auto time = std::filesystem::last_write_time(path, ec);
  if (ec) return s;
  s.exists = true;
  s.size = size;
  s.mtime = static_cast<std::int64_t>(time.time_since_epoch().count());
  return s;
}

bool filesUnchanged(const std::vector<FileStamp>& files) {
  for (const FileStamp& f : files)
    if (!f.exists || stampFile(f.path) != f) return false;
  return true;
}

}  // namespace tfd::graph
