#pragma once
// The hidden temporary files writers stage their output in, and their cleanup.
//
// A temporary for target `dir/name.ext` is `dir/.name.tfd-tmp<pid>-<n>.ext` (hidden, beside the
// target so the final rename stays on one file system; the extension stays last because some
// libraries choose the format from it). What can be left behind and who removes it:
//  - an error or a cancellation: the writer removes its temporary at once;
//  - SIGINT / SIGTERM (also a second one, which stops at once): the CLI's handler removes
//    every registered temporary (removeRegisteredTemporaries) before the process exits;
//  - SIGKILL, a crash or a power cut: the temporary stays. The next write of the same target
//    (or, for EXR slices, of the same pattern) removes temporaries whose process is gone
//    (removeStaleTemporaries).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace tfd::io {

/// A fresh temporary path for `target` (unique within this process).
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

/// What a temporary's file name says: the target's file name and the writing process.
struct TemporaryName {
  std::string target;  ///< e.g. "field.vdb"
  long pid = 0;
};
/// Parses a file name made by temporaryPathFor; nothing for any other name.
std::optional<TemporaryName> parseTemporaryName(std::string_view fileName);

/// Removes the temporaries in `folder` whose target file name satisfies `belongs` and whose
/// process no longer runs (never this process's own). Returns how many were removed; errors
/// are ignored (a folder that cannot be listed removes nothing).
int removeStaleTemporaries(const std::filesystem::path& folder,
                           const std::function<bool(const std::string& targetName)>& belongs);

/// Registers a temporary that is being written, so that a signal handler can remove it, for
/// the registration's lifetime. Registration is bounded (a few thousand live files); beyond
/// that a file is simply not registered (a later write still removes it as stale).
class RegisteredTemporary {
 public:
  explicit RegisteredTemporary(const std::filesystem::path& path);
  ~RegisteredTemporary();
  RegisteredTemporary(const RegisteredTemporary&) = delete;
  RegisteredTemporary& operator=(const RegisteredTemporary&) = delete;

 private:
  int slot_ = -1;
};
/// Unlinks every registered temporary. Async-signal-safe: only atomics and unlink(2); call
/// it from a signal handler right before _exit.
void removeRegisteredTemporaries() noexcept;

}  // namespace tfd::io
