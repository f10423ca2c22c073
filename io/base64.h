#pragma once
// Base64 encoding and decoding (RFC 4648 alphabet) for VTK XML binary data. Internal helper.
#include <cstddef>
#include <string>
#include <string_view>

namespace tfd::io {

/// Appends the base64 encoding of `bytes` (padded with '=').
void appendBase64(std::string& out, std::string_view bytes);

/// Decodes base64 text in groups of four characters, skipping white space. A group may end
/// with padding and decoding continues with the next group, so blocks encoded separately and
/// concatenated (as VTK writes headers and data) decode correctly.
class Base64Decoder {
 public:
  explicit Base64Decoder(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}
  /// Decodes until `out` has grown by `bytes` bytes; false when the text ends first or holds a
  /// character outside the alphabet (then `error()` says which).
  bool decode(std::string& out, std::size_t bytes);
  /// Decodes everything left.
  bool decodeAll(std::string& out);
  const std::string& error() const { return error_; }

 private:
  bool nextGroup(std::string& out);
  std::string_view text_;
  std::size_t pos_;
  std::string pending_;  // decoded bytes not yet handed out
  std::string error_;
};

}  // namespace tfd::io
