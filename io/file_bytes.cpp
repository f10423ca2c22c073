#include "io/file_bytes.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace tfd::io {

std::string readFileBytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw core::Error("cannot open file '" + path.string() + "': it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw core::Error("cannot open file '" + path.string() + "': " + std::strerror(errno));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw core::Error("cannot read file '" + path.string() + "'");
  return std::move(buffer).str();
}

void writeFileBytes(const std::filesystem::path& path, const std::string& bytes) {
  writeAtomically(path, [&](OutputFile& out) { out.write(bytes.data(), bytes.size()); });
}

}  // namespace tfd::io
