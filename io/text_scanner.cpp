#include "io/text_scanner.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "core/error.h"

namespace tfd::io {

TextScanner::TextScanner(std::string_view text, std::string fileName, char comment,
                         std::size_t offset, int firstLine)
    : text_(text),
      fileName_(std::move(fileName)),
      comment_(comment),
      next_(offset),
      lineNumber_(firstLine - 1),
      lastLine_(firstLine - 1) {}

bool TextScanner::nextLine() {
  while (next_ < text_.size()) {
    const std::size_t end = text_.find('\n', next_);
    std::string_view l = text_.substr(next_, end == std::string_view::npos ? end : end - next_);
    next_ = end == std::string_view::npos ? text_.size() : end + 1;
    ++lineNumber_;
    lastLine_ = lineNumber_;
    if (comment_ != 0) {
      if (const std::size_t c = l.find(comment_); c != std::string_view::npos) l = l.substr(0, c);
    }
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    line_ = l;
    pos_ = 0;
    if (!atLineEnd()) return true;
  }
  line_ = {};
  pos_ = 0;
  return false;
}

bool TextScanner::atLineEnd() {
  while (pos_ < line_.size() && std::isspace(static_cast<unsigned char>(line_[pos_]))) ++pos_;
  return pos_ >= line_.size();
}

std::string_view TextScanner::token() {
  if (atLineEnd()) return {};
  const std::size_t start = pos_;
  while (pos_ < line_.size() && !std::isspace(static_cast<unsigned char>(line_[pos_]))) ++pos_;
  return line_.substr(start, pos_ - start);
}

double TextScanner::number(std::string_view what) {
  const std::string_view t = token();
  double value;
  if (!parseNumber(t, value)) {
    fail("expected " + std::string(what) + " (a finite number), found " + describeToken(t));
  }
  return value;
}

long long TextScanner::integer(std::string_view what) {
  const std::string_view t = token();
  long long value;
  if (!parseInteger(t, value)) {
    fail("expected " + std::string(what) + " (an integer), found " + describeToken(t));
  }
  return value;
}

void TextScanner::expectLineEnd(std::string_view what) {
  const std::size_t before = pos_;
  const std::string_view t = token();
  if (!t.empty()) fail("unexpected " + describeToken(t) + " after " + std::string(what));
  pos_ = before;
}

// Messages quote the file's text: printableText() here, once for every reader, so no quoted
// line or token reaches a terminal raw (it leaves text that is already printable unchanged).
void TextScanner::fail(const std::string& message) const {
  throw core::Error("file '" + fileName_ + "', line " + std::to_string(lineNumber_) + ": " +
                    printableText(message));
}

void TextScanner::failAtEnd(const std::string& message) const {
  throw core::Error("file '" + fileName_ + "': " + printableText(message) +
                    " (file ended at line " + std::to_string(lastLine_) + ")");
}

bool parseNumber(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseInteger(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

std::string printableText(std::string_view text) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    // Length of a well-formed UTF-8 sequence starting here (0: not one).
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n > 1 && (c == 0xc0 || c == 0xc1 || c > 0xf4)) n = 0;  // overlong or beyond U+10FFFF
    for (std::size_t k = 1; k < n; ++k)
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) >> 6) != 2) n = 0;
    if (n == 1 && c >= 0x20 && c != 0x7f) {
      out += text[i];
    } else if (n > 1) {
      out.append(text.substr(i, n));
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
      n = 1;
    }
    i += n;
  }
  return out;
}

std::string describeToken(std::string_view token) {
  if (token.empty()) return "the end of the line";
  if (token.size() > 40) return "'" + printableText(token.substr(0, 40)) + "...'";
  return "'" + printableText(token) + "'";
}

}  // namespace tfd::io
