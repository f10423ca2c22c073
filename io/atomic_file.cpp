#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.h"
#include "io/temporary_files.h"

namespace tfd::io {

namespace fs = std::filesystem;

struct StagedFile::Registration {
  explicit Registration(const fs::path& p) : live(p) {}
  RegisteredTemporary live;
};

void prepareOutputPath(const fs::path& path) {
  if (path.empty()) throw core::Error("cannot write a file: the path is empty");
  std::error_code ec;
  if (!path.has_filename() || fs::is_directory(path, ec)) {
    throw core::Error("cannot write '" + path.string() + "': it is a folder, not a file");
  }
  if (path.has_parent_path()) {
    const fs::path parent = path.parent_path();
    if (fs::exists(parent, ec) && !fs::is_directory(parent, ec)) {
      throw core::Error("cannot write '" + path.string() + "': '" + parent.string() +
                        "' is a file, not a folder");
    }
    fs::create_directories(parent, ec);
    if (ec) {
      throw core::Error("cannot write '" + path.string() + "': cannot create the folder '" +
                        parent.string() + "': " + ec.message());
    }
  }
}

StagedFile::StagedFile(fs::path target) : target_(std::move(target)) {
  prepareOutputPath(target_);
  const std::string name = target_.filename().string();
  removeStaleTemporaries(target_.parent_path(),
                         [&](const std::string& targetName) { return targetName == name; });
  temp_ = temporaryPathFor(target_);
  registration_ = std::make_unique<Registration>(temp_);
}

StagedFile::~StagedFile() {
  if (committed_) return;
  std::error_code ec;
  fs::remove(temp_, ec);
}

void StagedFile::write(const std::function<void(OutputFile&)>& write) {
  OutputFile out(temp_, target_);
  write(out);
  out.close();
}

void StagedFile::writeByName(const std::function<void(const fs::path&)>& write) {
  write(temp_);
  const int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    throw core::Error("cannot write '" + target_.string() + "': " + std::strerror(errno));
  }
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL || errno == EROFS;
  const int error = errno;
  ::close(fd);
  if (!synced)
    throw core::Error("cannot write '" + target_.string() + "': " + std::strerror(error));
}

void StagedFile::commit() {
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec) {
    throw core::Error("cannot write '" + target_.string() + "': cannot rename the finished " +
                      "file into place: " + ec.message());
  }
  committed_ = true;
  registration_.reset();
}

void writeAtomically(const fs::path& path, const std::function<void(OutputFile&)>& write) {
  StagedFile file(path);
  file.write(write);
  file.commit();
}

void writeAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  StagedFile file(path);
  file.writeByName(write);
  file.commit();
}

}  // namespace tfd::io
