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
  // (Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "." + std::string.)
  std::string name(1, '.');
  name += path.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  name += path.extension().string();
  fs::path temp = path;
  temp.replace_filename(name);
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
