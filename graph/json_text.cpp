#include "graph/json_text.h"

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "graph/errors.h"

namespace tfd::graph {

namespace {

constexpr std::size_t kLineWidth = 100;

struct Frame {
  bool object = false;
  std::set<std::string> keys;
  std::string key;
  long index = -1;
};

std::string framesPointer(const std::vector<Frame>& frames) {
  std::string pointer;
  for (const Frame& f : frames) {
    if (f.object) {
      if (f.key.empty() && f.keys.empty()) break;
      pointer = pointerJoin(pointer, f.key);
    } else {
      if (f.index < 0) break;
      pointer = pointerJoin(pointer, static_cast<std::size_t>(f.index));
    }
  }
  return pointer;
}

bool isScalar(const Json& j) { return !j.is_structured(); }

bool isFlat(const Json& j) {  // scalars only, or containers of scalars
  if (isScalar(j)) return true;
  for (const auto& item : j) {
    if (isScalar(item)) continue;
    if (item.is_array() || item.is_object()) {
      for (const auto& inner : item)
        if (!isScalar(inner)) return false;
      continue;
    }
    return false;
  }
  return true;
}

void compactInto(const Json& j, std::string& out) {
  if (j.is_object()) {
    out += '{';
    bool first = true;
    for (const auto& [k, v] : j.items()) {
      if (!first) out += ", ";
      first = false;
      out += Json(k).dump();
      out += ": ";
      compactInto(v, out);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    bool first = true;
    for (const auto& v : j) {
      if (!first) out += ", ";
      first = false;
      compactInto(v, out);
    }
    out += ']';
  } else {
    out += j.dump();
  }
}

void prettyInto(const Json& j, std::string& out, std::size_t indent, std::size_t prefixWidth) {
  if (isScalar(j) || j.empty()) {
    compactInto(j, out);
    return;
  }
  if (isFlat(j)) {
    std::string line;
    compactInto(j, line);
    if (indent + prefixWidth + line.size() + 1 <= kLineWidth) {
      out += line;
      return;
    }
  }
  const std::string inner(indent + 2, ' ');
  out += j.is_object() ? "{\n" : "[\n";
  bool first = true;
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      if (!first) out += ",\n";
      first = false;
      std::string key = Json(k).dump() + ": ";
      out += inner + key;
      prettyInto(v, out, indent + 2, key.size());
    }
  } else {
    for (const auto& v : j) {
      if (!first) out += ",\n";
      first = false;
      out += inner;
      prettyInto(v, out, indent + 2, 0);
    }
  }
  out += '\n';
  out.append(indent, ' ');
  out += j.is_object() ? "}" : "]";
}

/// A char iterator that records how far the parser has read (the largest offset reached).
struct CountingIterator {
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  std::size_t* consumed = nullptr;  ///< shared by the begin iterator and its copies
  const char* base = nullptr;

  CountingIterator() = default;
  CountingIterator(const char* position, std::size_t* counter)
      : p(position), consumed(counter), base(position) {}
  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    if (consumed) *consumed = std::max(*consumed, static_cast<std::size_t>(p - base));
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

std::string withoutPrefix(std::string message) {
  if (auto pos = message.find("] "); message.starts_with("[json.exception") && pos != message.npos)
    message = message.substr(pos + 2);
  return message;
}

/// "line L, column C" of the byte before offset `end` (the last one read).
std::string lineAndColumn(std::string_view text, std::size_t end) {
  end = std::min(end, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// The pointer of the value being read when parsing failed: the last key of an object, or
/// the next element of an array (its index is only counted once the value is complete).
std::string failurePointer(std::vector<Frame> frames) {
  if (!frames.empty() && !frames.back().object) ++frames.back().index;
  return framesPointer(frames);
}

}  // namespace

std::string pointerJoin(std::string_view pointer, std::string_view token) {
  std::string out(pointer);
  out += '/';
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string pointerJoin(std::string_view pointer, std::size_t index) {
  return std::string(pointer) + "/" + std::to_string(index);
}

Json parseJsonText(std::string_view text, const std::string& source) {
  std::vector<Frame> frames;
  auto enterChild = [&frames] {
    if (!frames.empty() && !frames.back().object) ++frames.back().index;
  };
  Json::parser_callback_t callback = [&](int, nlohmann::json::parse_event_t event,
                                         Json& parsed) -> bool {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
        enterChild();
        frames.emplace_back().object = true;
        break;
      case E::array_start:
        enterChild();
        frames.emplace_back().object = false;
        break;
      case E::object_end:
      case E::array_end:
        if (!frames.empty()) frames.pop_back();
        break;
      case E::key: {
        Frame& f = frames.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second)
          throw LoadError(source, framesPointer(frames),
                          "duplicate key \"" + f.key + "\" (every key may appear only once)");
        break;
      }
      case E::value:
        enterChild();
        break;
    }
    return true;
  };
  // The reader's position, for errors nlohmann reports without one (a number beyond the
  // double range, 1e400, is an out_of_range error at the end of the token).
  std::size_t consumed = 0;
  try {
    return Json::parse(CountingIterator{text.data(), &consumed},
                       CountingIterator{text.data() + text.size(), nullptr}, callback);
  } catch (const nlohmann::json::parse_error& e) {
    throw LoadError(source, "", "invalid JSON: " + printableText(withoutPrefix(e.what())));
  } catch (const nlohmann::json::out_of_range& e) {
    std::string message = withoutPrefix(e.what());
    if (e.id == 406) {  // "number overflow parsing '1e400'"
      const std::size_t quote = message.find('\'');
      const std::string token = quote == std::string::npos ? std::string() : message.substr(quote);
      message = "the number " + printableText(token) +
                " is beyond the range of a double (about ±1.8e308)";
    }
    throw LoadError(source, failurePointer(frames),
                    message + " at " + lineAndColumn(text, consumed));
  } catch (const nlohmann::json::exception& e) {
    throw LoadError(source, failurePointer(frames),
                    "invalid JSON: " + printableText(withoutPrefix(e.what())) + " at " +
                        lineAndColumn(text, consumed));
  }
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

std::string formatJson(const Json& json) {
  std::string out;
  prettyInto(json, out, 0, 0);
  out += '\n';
  return out;
}

std::string compactJson(const Json& json) {
  std::string out;
  compactInto(json, out);
  return out;
}

std::string describeJson(const Json& json) {
  std::string text = compactJson(json);
  if (text.size() <= 60) return text;
  if (json.is_object()) return "an object with " + std::to_string(json.size()) + " keys";
  if (json.is_array()) return "an array of " + std::to_string(json.size()) + " elements";
  return text.substr(0, 57) + "...";
}

}  // namespace tfd::graph
