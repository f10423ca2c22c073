#pragma once
// Writers never leave a partial file: they write to a hidden temporary beside the target
// (io/temporary_files.h), check that it is complete (io/output_file.h) and only then rename it
// into place. An existing file at the target stays untouched on any failure.
#include <filesystem>
#include <functional>

#include "io/output_file.h"

namespace tfd::io {

/// Checks that `path` can name a file to write: not empty, not ending in a folder separator,
/// not an existing folder; creates missing parent folders. Throws core::Error naming the path
/// ("cannot write 'out/': it is a folder, not a file").
void prepareOutputPath(const std::filesystem::path& path);

/// One output file staged in a temporary until commit(). The destructor removes the temporary
/// unless it was committed. Construction prepares the path (prepareOutputPath) and removes
/// stale temporaries of the same target left by processes that are gone.
class StagedFile {
 public:
  explicit StagedFile(std::filesystem::path target);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temp_; }

  /// Writes the temporary through `write` and checks it (OutputFile::close). Errors name the
  /// target, never the temporary.
  void write(const std::function<void(OutputFile& out)>& write);
  /// For libraries that open files by name: `write(temporary())`, then the temporary is
  /// fsynced and checked to exist.
  void writeByName(const std::function<void(const std::filesystem::path& temp)>& write);
  /// Renames the temporary over the target. Throws core::Error naming the target.
  void commit();

 private:
  std::filesystem::path target_, temp_;
  struct Registration;
  std::unique_ptr<Registration> registration_;
  bool committed_ = false;
};

/// Writes `path` through `write` and renames it into place (StagedFile).
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(OutputFile& out)>& write);

/// The same for a library that opens the file by name (StagedFile::writeByName): prefer the
/// OutputFile form, which sees every write error.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& tempPath)>& write);

}  // namespace tfd::io
