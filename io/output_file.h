#pragma once
// A binary output file that notices every failure: a short or failed write (a full disk,
// ENOSPC; a file-size limit, EFBIG), a failed flush, fsync or close, and a file on disk whose
// size differs from what was written. std::ofstream and the libraries built on it (OpenVDB's
// io::File, OpenEXR's StdOFStream on close) lose some of these; every tfd writer writes
// through this class (usually via io::writeAtomically) so none of them can report success for
// a truncated file.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>

namespace tfd::io {

class OutputFile {
 public:
  /// Creates or truncates `path` (mode 0666 minus umask). `target` is the name used in error
  /// messages (the final file when `path` is its hidden temporary). Throws core::Error
  /// "cannot write '<target>': <reason>" when the file cannot be created.
  OutputFile(const std::filesystem::path& path, const std::filesystem::path& target);
  /// Closes the file without any check when close() was not called (after an error).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Buffered stream over the file, seekable. A failure sets the stream's badbit and is
  /// remembered; close() reports it.
  std::ostream& stream() { return *stream_; }
  /// Unformatted write through the same buffer; false once anything failed.
  bool write(const void* data, std::size_t size);
  /// Current write position (flushes the buffer).
  std::uint64_t tell();
  /// Moves the write position (flushes the buffer); false on failure.
  bool seek(std::uint64_t position);
  /// True once a write, flush or seek failed.
  bool failed() const;

  /// Flushes, fsyncs and closes the file, then checks that nothing failed and that the file
  /// holds every byte written (its size is the largest position written). Throws core::Error
  /// "cannot write '<target>': <reason>" otherwise. Call once, after the last write.
  void close();

  const std::filesystem::path& target() const { return target_; }

 private:
  class Buffer;
  std::filesystem::path target_;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
};

}  // namespace tfd::io
