#include "graph/atomic_write.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "graph/errors.h"

namespace tfd::graph {

void writeTextFileAtomically(const std::filesystem::path& path, std::string_view content) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path temp =
      path.parent_path() / (std::string(".") + path.filename().string() + ".tmp" +
                            std::to_string(getpid()) + "-" + std::to_string(counter++));
  auto fail = [&](const std::string& why) {
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    throw GraphError("cannot write " + path.string() + ": " + why);
  };
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) fail(std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  const int writeErrno = errno;
  const bool flushed = std::fflush(f) == 0 && fsync(fileno(f)) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!written) fail(std::strerror(writeErrno));
  if (!flushed || !closed) fail(std::strerror(errno));
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) fail(ec.message());
}

}  // namespace tfd::graph
