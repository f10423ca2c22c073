#include "graph/json_text.h"

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
  try {
    return Json::parse(text.begin(), text.end(), callback);
  } catch (const nlohmann::json::parse_error& e) {
    std::string message = e.what();
    if (auto pos = message.find("] ");
        message.starts_with("[json.exception") && pos != message.npos)
      message = message.substr(pos + 2);
    throw LoadError(source, "", "invalid JSON: " + message);
  }
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
