#include "io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <streambuf>
#include <string>
#include <vector>

#include "core/error.h"

namespace tfd::io {

/// A std::streambuf over a POSIX descriptor that keeps the first failure's errno and the
/// largest offset written.
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), data_(kSize) { setp(data_.data(), data_.data() + kSize); }
  ~Buffer() override {
    if (fd_ >= 0) ::close(fd_);
  }

  bool failed() const { return error_ != 0; }
  int error() const { return error_; }

  bool writeBytes(const char* data, std::size_t n) {
    if (failed()) return false;
    const std::size_t room = static_cast<std::size_t>(epptr() - pptr());
    if (n <= room) {
      std::memcpy(pptr(), data, n);
      pbump(static_cast<int>(n));
      return true;
    }
    return flush() && writeDirect(data, n);
  }

  /// Writes the buffered bytes to the descriptor.
  bool flush() {
    if (failed()) return false;
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(data_.data(), data_.data() + kSize);
    return writeDirect(data_.data(), n);
  }

  std::uint64_t position() {
    if (!flush()) return position_;
    return position_;
  }

  bool seekTo(std::uint64_t position) {
    if (!flush()) return false;
    if (::lseek(fd_, static_cast<off_t>(position), SEEK_SET) < 0) return fail(errno);
    position_ = position;
    return true;
  }

  /// Flush, fsync, fstat, close. Returns the errno of the first failure (0 when none) and the
  /// size found on disk.
  int finish(std::uint64_t& sizeOnDisk) {
    flush();
    if (!failed() && ::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS) fail(errno);
    struct stat st {};
    if (!failed() && ::fstat(fd_, &st) != 0) fail(errno);
    sizeOnDisk = static_cast<std::uint64_t>(st.st_size);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && !failed()) fail(errno);
    return error_;
  }

  std::uint64_t end() const { return end_; }

 protected:
  int_type overflow(int_type c) override {
    if (!flush()) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    return writeBytes(s, static_cast<std::size_t>(n)) ? n : 0;
  }
  int sync() override { return flush() ? 0 : -1; }
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    if (!flush()) return pos_type(off_type(-1));
    std::uint64_t target = 0;
    if (dir == std::ios_base::beg) {
      target = static_cast<std::uint64_t>(off);
    } else if (dir == std::ios_base::cur) {
      target = static_cast<std::uint64_t>(static_cast<off_type>(position_) + off);
    } else {
      target = static_cast<std::uint64_t>(static_cast<off_type>(end_) + off);
    }
    if (off == 0 && dir == std::ios_base::cur) return pos_type(off_type(position_));
    return seekTo(target) ? pos_type(off_type(target)) : pos_type(off_type(-1));
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode) override {
    return seekTo(static_cast<std::uint64_t>(off_type(pos))) ? pos : pos_type(off_type(-1));
  }

 private:
  static constexpr std::size_t kSize = 1 << 20;

  bool fail(int error) {
    if (error_ == 0) error_ = error != 0 ? error : EIO;
    return false;
  }

  bool writeDirect(const char* data, std::size_t n) {
    while (n > 0) {
      const ssize_t written = ::write(fd_, data, n);
      if (written < 0) {
        if (errno == EINTR) continue;
        return fail(errno);
      }
      if (written == 0) return fail(EIO);
      data += written;
      n -= static_cast<std::size_t>(written);
      position_ += static_cast<std::uint64_t>(written);
      end_ = std::max(end_, position_);
    }
    return true;
  }

  int fd_ = -1;
  std::vector<char> data_;
  std::uint64_t position_ = 0, end_ = 0;
  int error_ = 0;
};

OutputFile::OutputFile(const std::filesystem::path& path, const std::filesystem::path& target)
    : target_(target) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    throw core::Error("cannot write '" + target.string() + "': " + std::strerror(errno));
  }
  buffer_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  stream_.reset();
  buffer_.reset();
}

bool OutputFile::write(const void* data, std::size_t size) {
  return buffer_->writeBytes(static_cast<const char*>(data), size);
}

std::uint64_t OutputFile::tell() { return buffer_->position(); }

bool OutputFile::seek(std::uint64_t position) { return buffer_->seekTo(position); }

bool OutputFile::failed() const { return buffer_->failed() || stream_->bad(); }

void OutputFile::close() {
  const bool streamBad = stream_->bad();
  std::uint64_t size = 0;
  const int error = buffer_->finish(size);
  auto fail = [&](const std::string& why) {
    throw core::Error("cannot write '" + target_.string() + "': " + why);
  };
  if (error != 0) {
    fail(std::strerror(error));
  }
  if (streamBad) fail("the writer reported a stream error");
  if (size != buffer_->end()) {
    fail("only " + std::to_string(size) + " of " + std::to_string(buffer_->end()) +
         " bytes reached the disk");
  }
}

}  // namespace tfd::io
