#include "io/base64.h"

#include <algorithm>
#include <cctype>

#include "io/text_scanner.h"

namespace tfd::io {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int valueOf(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

void appendBase64(std::string& out, std::string_view bytes) {
  out.reserve(out.size() + (bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    unsigned v = (unsigned char)bytes[i] << 16;
    if (rest == 2) v |= (unsigned char)bytes[i + 1] << 8;
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += rest == 2 ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
}

bool Base64Decoder::nextGroup(std::string& out) {
  char group[4];
  int n = 0;
  while (n < 4 && pos_ < text_.size()) {
    const char c = text_[pos_++];
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (c != '=' && valueOf(c) < 0) {
      error_ = "invalid base64 character '" + printableText(std::string_view(&c, 1)) + "'";
      return false;
    }
    group[n++] = c;
  }
  if (n == 0) {
    error_ = "base64 data ended early";
    return false;
  }
  if (n < 4) {
    error_ = "base64 data ended inside a group";
    return false;
  }
  int pad = 0;
  unsigned v = 0;
  for (int k = 0; k < 4; ++k) {
    if (group[k] == '=') {
      ++pad;
      v <<= 6;
    } else {
      if (pad > 0) {
        error_ = "misplaced base64 padding";
        return false;
      }
      v = v << 6 | unsigned(valueOf(group[k]));
    }
  }
  if (pad > 2) {
    error_ = "misplaced base64 padding";
    return false;
  }
  out += char(v >> 16 & 255);
  if (pad < 2) out += char(v >> 8 & 255);
  if (pad < 1) out += char(v & 255);
  return true;
}

bool Base64Decoder::decode(std::string& out, std::size_t bytes) {
  const std::size_t target = out.size() + bytes;
  // Hand out what is pending first.
  const std::size_t fromPending = std::min(bytes, pending_.size());
  out.append(pending_, 0, fromPending);
  pending_.erase(0, fromPending);
  while (out.size() < target) {
    if (!nextGroup(out)) return false;
  }
  if (out.size() > target) {
    pending_.insert(0, out, target);
    out.resize(target);
  }
  return true;
}

bool Base64Decoder::decodeAll(std::string& out) {
  out += pending_;
  pending_.clear();
  for (;;) {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (pos_ >= text_.size()) return true;
    if (!nextGroup(out)) return false;
  }
}

}  // namespace tfd::io
