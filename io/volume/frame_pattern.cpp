#include "io/volume/frame_pattern.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/error.h"

namespace tfd::io {

namespace {

/// Where the frame placeholder sits in a pattern and how wide it is.
struct Placeholder {
  std::size_t begin = 0, end = 0;  ///< [begin, end) in the pattern
  int width = 0;                   ///< zero-padding width (0: none)
};

/// Finds the single placeholder; `%%` is a literal percent sign. Throws core::Error otherwise.
Placeholder findPlaceholder(const std::string& pattern) {
  std::vector<Placeholder> found;
  for (std::size_t i = 0; i < pattern.size();) {
    if (pattern[i] == '%') {
      if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
        i += 2;
        continue;
      }
      std::size_t j = i + 1;
      int width = 0;
      while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) {
        width = std::min(width * 10 + (pattern[j] - '0'), 64);
        ++j;
      }
      if (j >= pattern.size() || pattern[j] != 'd') {
        throw core::Error("EXR path pattern '" + pattern +
                          "': only %d, %0Nd or a run of # may stand for the slice number "
                          "(write %% for a percent sign)");
      }
      found.push_back({i, j + 1, width});
      i = j + 1;
    } else if (pattern[i] == '#') {
      std::size_t j = i;
      while (j < pattern.size() && pattern[j] == '#') ++j;
      found.push_back({i, j, static_cast<int>(std::min<std::size_t>(j - i, 64))});
      i = j;
    } else {
      ++i;
    }
  }
  if (found.size() != 1) {
    throw core::Error("EXR path pattern '" + pattern + "' must hold exactly one slice number " +
                      "placeholder (like %04d or ####), found " + std::to_string(found.size()));
  }
  return found.front();
}

std::string unescapePercent(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
  }
  return out;
}

}  // namespace

std::string expandFramePattern(const std::string& pattern, int frame) {
  const Placeholder ph = findPlaceholder(pattern);
  char digits[96];
  std::snprintf(digits, sizeof digits, "%0*d", ph.width, frame);
  return unescapePercent(pattern.substr(0, ph.begin)) + digits +
         unescapePercent(pattern.substr(ph.end));
}

bool framePlaceholderInFileName(const std::string& pattern) {
  const Placeholder ph = findPlaceholder(pattern);
  return pattern.find('/', ph.end) == std::string::npos;
}

std::optional<int> frameOfFileName(const std::string& pattern, const std::string& fileName) {
  const std::string name = std::filesystem::path(pattern).filename().string();
  const Placeholder ph = findPlaceholder(name);
  const std::string prefix = unescapePercent(name.substr(0, ph.begin));
  const std::string suffix = unescapePercent(name.substr(ph.end));
  if (fileName.size() <= prefix.size() + suffix.size() || !fileName.starts_with(prefix) ||
      !fileName.ends_with(suffix))
    return std::nullopt;
  const std::string digits =
      fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
  const std::size_t first = digits[0] == '-' ? 1 : 0;
  if (digits.size() == first || digits.size() - first > 9) return std::nullopt;
  for (std::size_t i = first; i < digits.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(digits[i]))) return std::nullopt;
  const int frame = std::stoi(digits);
  if (expandFramePattern(name, frame) != fileName) return std::nullopt;
  return frame;
}

}  // namespace tfd::io
