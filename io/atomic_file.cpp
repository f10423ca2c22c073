#include "io/atomic_file.h"

#include <atomic>
#include <string>
#include <system_error>

#include <unistd.h>

#include "core/error.h"

namespace tfd::io {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
  namespace fs = std::filesystem;
  static std::atomic<unsigned> counter{0};
  std::error_code ec;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) {
      throw core::Error("cannot create folder '" + path.parent_path().string() +
                        "': " + ec.message());
    }
  }
  // Keep the extension last: some libraries choose the format from it.
  fs::path temp = path;
  temp.replace_filename("." + path.stem().string() + ".tmp" + std::to_string(::getpid()) + "-" +
                        std::to_string(counter++) + path.extension().string());
  try {
    write(temp);
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw core::Error("cannot write '" + path.string() + "': " + ec.message());
  }
}

}  // namespace tfd::io
