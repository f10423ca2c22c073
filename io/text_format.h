#pragma once
// Exact, locale-independent number formatting for text mesh writers. Internal helper.
#include <charconv>
#include <string>

namespace tfd::io {

/// Appends the shortest decimal that reads back as exactly `value` (std::to_chars).
inline void appendNumber(std::string& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, end);
}

inline void appendNumber(std::string& out, long long value) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, end);
}

inline void appendNumber(std::string& out, int value) { appendNumber(out, (long long)value); }
inline void appendNumber(std::string& out, std::size_t value) {
  appendNumber(out, (long long)value);
}

}  // namespace tfd::io
