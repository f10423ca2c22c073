#include "graph/param.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "graph/errors.h"
#include "graph/hash.h"
#include "graph/json_text.h"

namespace tfd::graph {

namespace {

std::string number(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

std::string rangeText(const ParamDecl& d, bool integer) {
  auto fmt = [&](double v) {
    return integer ? std::to_string(static_cast<long long>(v)) : number(v);
  };
  if (d.min && d.max) return "[" + fmt(*d.min) + ", " + fmt(*d.max) + "]";
  if (d.min) return ">= " + fmt(*d.min);
  if (d.max) return "<= " + fmt(*d.max);
  return {};
}

std::string rangeSuffix(const ParamDecl& d, bool integer, std::string_view each = "") {
  std::string r = rangeText(d, integer);
  if (r.empty()) return {};
  if (r[0] == '[') return std::string(each) + " in " + r;
  return std::string(each) + " " + r;
}

/// "\"a\", \"b\", \"c\"" for the choices of an enum.
std::string quotedChoices(const ParamDecl& d) {
  std::string out;
  for (std::size_t i = 0; i < d.choices.size(); ++i)
    out += (i ? ", \"" : "\"") + d.choices[i] + "\"";
  return out;
}

[[noreturn]] void mismatch(const ParamDecl& d, const std::string& found) {
  throw GraphError("expected " + describeExpected(d) + ", found " + found);
}

std::string foundText(const ParamValue& v) { return describeJson(paramToJson(v)); }

bool inRange(const ParamDecl& d, double v) {
  return std::isfinite(v) && (!d.min || v >= *d.min) && (!d.max || v <= *d.max);
}

double jsonNumber(const ParamDecl& d, const Json& j) {
  if (!j.is_number()) mismatch(d, describeJson(j));
  return j.get<double>();
}

}  // namespace

std::string ParamDecl::displayLabel() const {
  if (!label.empty()) return label;
  std::string out = name;
  std::replace(out.begin(), out.end(), '_', ' ');
  if (!out.empty() && out[0] >= 'a' && out[0] <= 'z') out[0] = static_cast<char>(out[0] - 32);
  return out;
}

std::string_view kindName(ParamKind kind) {
  switch (kind) {
    case ParamKind::Bool:
      return "bool";
    case ParamKind::Int:
      return "int";
    case ParamKind::Double:
      return "double";
    case ParamKind::String:
      return "string";
    case ParamKind::Vec3:
      return "vec3";
    case ParamKind::Vec3List:
      return "vec3 list";
    case ParamKind::DoubleList:
      return "double list";
    case ParamKind::StringList:
      return "string list";
  }
  return "?";
}

std::string_view hintName(UiHint hint) {
  switch (hint) {
    case UiHint::Auto:
      return "auto";
    case UiHint::Slider:
      return "slider";
    case UiHint::LogSlider:
      return "log-slider";
    case UiHint::Angle:
      return "angle";
    case UiHint::Position:
      return "position";
    case UiHint::Direction:
      return "direction";
    case UiHint::InputFile:
      return "input-file";
    case UiHint::OutputFile:
      return "output-file";
    case UiHint::Multiline:
      return "multiline";
  }
  return "?";
}

std::string typeLabel(const ParamDecl& d) {
  if (d.kind == ParamKind::String) {
    if (!d.choices.empty()) return "enum";
    if (d.isInputFile()) return "input file";
    if (d.isOutputFile()) return "output file";
  }
  if (d.kind == ParamKind::DoubleList && d.size) return "double[" + std::to_string(*d.size) + "]";
  if (d.kind == ParamKind::StringList && !d.choices.empty()) return "enum list";
  return std::string(kindName(d.kind));
}

std::string describeExpected(const ParamDecl& d) {
  switch (d.kind) {
    case ParamKind::Bool:
      return "true or false";
    case ParamKind::Int:
      return "an integer" + rangeSuffix(d, true);
    case ParamKind::Double:
      return "a number" + rangeSuffix(d, false);
    case ParamKind::String:
      if (d.choices.empty()) return d.isPath() ? "a file path (string)" : "a string";
      return "one of " + quotedChoices(d);
    case ParamKind::StringList: {
      std::string out = d.choices.empty() ? "an array of strings"
                                          : "an array of strings, each one of " + quotedChoices(d);
      if (d.minSize) out += " (at least " + std::to_string(d.minSize) + ")";
      return out;
    }
    case ParamKind::Vec3:
      return "an array of 3 numbers [x, y, z]" + rangeSuffix(d, false, " each");
    case ParamKind::Vec3List: {
      std::string out = "an array of [x, y, z] points";
      if (d.minSize) out += " (at least " + std::to_string(d.minSize) + ")";
      return out + rangeSuffix(d, false, ", coordinates");
    }
    case ParamKind::DoubleList: {
      std::string out =
          d.size ? "an array of " + std::to_string(*d.size) + " numbers" : "an array of numbers";
      if (!d.size && d.minSize) out += " (at least " + std::to_string(d.minSize) + ")";
      return out + rangeSuffix(d, false, " each");
    }
  }
  return "?";
}

std::string describeConstraints(const ParamDecl& d) {
  if ((d.kind == ParamKind::String || d.kind == ParamKind::StringList) && !d.choices.empty()) {
    std::string out;
    for (std::size_t i = 0; i < d.choices.size(); ++i) out += (i ? " | " : "") + d.choices[i];
    if (d.kind == ParamKind::StringList && d.minSize)
      out = "at least " + std::to_string(d.minSize) + " of " + out;
    return out;
  }
  std::string out = rangeText(d, d.kind == ParamKind::Int);
  auto addSize = [&](const std::string& s) { out = out.empty() ? s : s + ", " + out; };
  if (d.kind == ParamKind::DoubleList && d.size) addSize(std::to_string(*d.size) + " values");
  if ((d.kind == ParamKind::DoubleList || d.kind == ParamKind::Vec3List) && !d.size && d.minSize)
    addSize("at least " + std::to_string(d.minSize));
  if (d.isPath() && !d.fileFilter.empty()) addSize(d.fileFilter);
  return out;
}

namespace {
void runCheck(const ParamDecl& d, const ParamValue& value) {
  if (!d.check) return;
  try {
    d.check(value);
  } catch (const std::exception& e) {
    throw GraphError(e.what());
  }
}

ParamValue checkKindAndRange(const ParamDecl& d, ParamValue value) {
  const int want = static_cast<int>(d.kind);
  if (d.kind == ParamKind::Double && std::holds_alternative<std::int64_t>(value))
    value = static_cast<double>(std::get<std::int64_t>(value));
  if (static_cast<int>(value.index()) != want) mismatch(d, foundText(value));
  switch (d.kind) {
    case ParamKind::Bool:
      break;
    case ParamKind::Int: {
      double v = static_cast<double>(std::get<std::int64_t>(value));
      if (!inRange(d, v)) mismatch(d, foundText(value));
      break;
    }
    case ParamKind::Double:
      if (!inRange(d, std::get<double>(value))) mismatch(d, foundText(value));
      break;
    case ParamKind::String: {
      const auto& s = std::get<std::string>(value);
      if (!d.choices.empty() && std::find(d.choices.begin(), d.choices.end(), s) == d.choices.end())
        mismatch(d, foundText(value));
      break;
    }
    case ParamKind::Vec3:
      for (double c : std::get<Vec3Param>(value))
        if (!inRange(d, c)) mismatch(d, foundText(value));
      break;
    case ParamKind::Vec3List: {
      const auto& list = std::get<std::vector<Vec3Param>>(value);
      if (list.size() < d.minSize) mismatch(d, foundText(value));
      for (const auto& p : list)
        for (double c : p)
          if (!inRange(d, c)) mismatch(d, foundText(value));
      break;
    }
    case ParamKind::DoubleList: {
      const auto& list = std::get<std::vector<double>>(value);
      if ((d.size && list.size() != *d.size) || list.size() < d.minSize)
        mismatch(d, foundText(value));
      for (double c : list)
        if (!inRange(d, c)) mismatch(d, foundText(value));
      break;
    }
    case ParamKind::StringList: {
      const auto& list = std::get<std::vector<std::string>>(value);
      if (list.size() < d.minSize) mismatch(d, foundText(value));
      for (const auto& s : list)
        if (!d.choices.empty() &&
            std::find(d.choices.begin(), d.choices.end(), s) == d.choices.end())
          mismatch(d, foundText(value));
      break;
    }
  }
  return value;
}
}  // namespace

ParamValue checkParamValue(const ParamDecl& d, ParamValue value) {
  value = checkKindAndRange(d, std::move(value));
  runCheck(d, value);
  return value;
}

ParamValue paramFromJson(const ParamDecl& d, const Json& j) {
  // Range, choice and size errors quote the JSON as written, not the converted value.
  auto checkParamValue = [&](const ParamDecl& decl, ParamValue v) {
    try {
      v = checkKindAndRange(decl, std::move(v));
    } catch (const GraphError&) {
      mismatch(decl, describeJson(j));
    }
    runCheck(decl, v);
    return v;
  };
  switch (d.kind) {
    case ParamKind::Bool:
      if (!j.is_boolean()) mismatch(d, describeJson(j));
      return checkParamValue(d, j.get<bool>());
    case ParamKind::Int: {
      if (j.is_number_integer()) {
        if (j.is_number_unsigned() &&
            j.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
          mismatch(d, describeJson(j));
        return checkParamValue(d, j.get<std::int64_t>());
      }
      if (j.is_number_float()) {  // accept integral floats such as 1e6
        double v = j.get<double>();
        if (std::trunc(v) == v && std::abs(v) < 9.0e18)
          return checkParamValue(d, static_cast<std::int64_t>(v));
      }
      mismatch(d, describeJson(j));
    }
    case ParamKind::Double:
      return checkParamValue(d, jsonNumber(d, j));
    case ParamKind::String:
      if (!j.is_string()) mismatch(d, describeJson(j));
      return checkParamValue(d, j.get<std::string>());
    case ParamKind::Vec3: {
      if (!j.is_array() || j.size() != 3) mismatch(d, describeJson(j));
      Vec3Param v{};
      for (std::size_t i = 0; i < 3; ++i) v[i] = jsonNumber(d, j[i]);
      return checkParamValue(d, v);
    }
    case ParamKind::Vec3List: {
      if (!j.is_array()) mismatch(d, describeJson(j));
      std::vector<Vec3Param> list;
      for (const auto& p : j) {
        if (!p.is_array() || p.size() != 3) mismatch(d, describeJson(j));
        Vec3Param v{};
        for (std::size_t i = 0; i < 3; ++i) {
          if (!p[i].is_number()) mismatch(d, describeJson(j));
          v[i] = p[i].get<double>();
        }
        list.push_back(v);
      }
      return checkParamValue(d, std::move(list));
    }
    case ParamKind::DoubleList: {
      if (!j.is_array()) mismatch(d, describeJson(j));
      std::vector<double> list;
      for (const auto& c : j) {
        if (!c.is_number()) mismatch(d, describeJson(j));
        list.push_back(c.get<double>());
      }
      return checkParamValue(d, std::move(list));
    }
    case ParamKind::StringList: {
      if (!j.is_array()) mismatch(d, describeJson(j));
      std::vector<std::string> list;
      for (const auto& c : j) {
        if (!c.is_string()) mismatch(d, describeJson(j));
        list.push_back(c.get<std::string>());
      }
      return checkParamValue(d, std::move(list));
    }
  }
  mismatch(d, describeJson(j));
}

Json paramToJson(const ParamValue& value) {
  return std::visit(
      [](const auto& v) -> Json {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Vec3Param>) {
          return Json::array({v[0], v[1], v[2]});
        } else if constexpr (std::is_same_v<V, std::vector<Vec3Param>>) {
          Json out = Json::array();
          for (const auto& p : v) out.push_back(Json::array({p[0], p[1], p[2]}));
          return out;
        } else if constexpr (std::is_same_v<V, std::vector<double>> ||
                             std::is_same_v<V, std::vector<std::string>>) {
          Json out = Json::array();
          for (const auto& c : v) out.push_back(c);
          return out;
        } else {
          return Json(v);
        }
      },
      value);
}

ParamValue paramFromText(const ParamDecl& d, std::string_view text) {
  auto trimmed = [](std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
  };
  std::string quoted = "\"";
  quoted += text;
  quoted += '"';
  switch (d.kind) {
    case ParamKind::String:
      return checkParamValue(d, std::string(text));
    case ParamKind::Bool: {
      std::string t(trimmed(text));
      std::transform(t.begin(), t.end(), t.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      if (t == "true" || t == "1" || t == "yes" || t == "on") return true;
      if (t == "false" || t == "0" || t == "no" || t == "off") return false;
      mismatch(d, quoted);
    }
    case ParamKind::Int: {
      std::string_view t = trimmed(text);
      std::int64_t v = 0;
      auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
      if (ec != std::errc() || end != t.data() + t.size() || t.empty()) mismatch(d, quoted);
      return checkParamValue(d, v);
    }
    case ParamKind::Double: {
      std::string_view t = trimmed(text);
      if (!t.empty() && t.front() == '+') t.remove_prefix(1);
      double v = 0;
      auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
      if (ec != std::errc() || end != t.data() + t.size() || t.empty() || !std::isfinite(v))
        mismatch(d, quoted);
      return checkParamValue(d, v);
    }
    case ParamKind::Vec3:
    case ParamKind::Vec3List:
    case ParamKind::DoubleList: {
      std::string t(trimmed(text));
      if (d.kind != ParamKind::Vec3List && (t.empty() || t.front() != '[')) t = "[" + t + "]";
      Json j = Json::parse(t, nullptr, /*allow_exceptions=*/false);
      if (j.is_discarded()) mismatch(d, quoted + " (not valid JSON)");
      return paramFromJson(d, j);
    }
    case ParamKind::StringList: {
      // JSON (["a", "b"]) or comma-separated words (a,b); an empty text is the empty list.
      const std::string_view t = trimmed(text);
      if (!t.empty() && t.front() == '[') {
        Json j = Json::parse(t, nullptr, /*allow_exceptions=*/false);
        if (j.is_discarded()) mismatch(d, quoted + " (not valid JSON)");
        return paramFromJson(d, j);
      }
      std::vector<std::string> list;
      for (std::size_t start = 0; start <= t.size() && !t.empty();) {
        const std::size_t comma = std::min(t.find(',', start), t.size());
        const std::string_view item = trimmed(t.substr(start, comma - start));
        if (item.empty()) mismatch(d, quoted + " (an empty item)");
        list.emplace_back(item);
        start = comma + 1;
      }
      return checkParamValue(d, std::move(list));
    }
  }
  mismatch(d, quoted);
}

std::string formatParamValue(const ParamValue& value) { return compactJson(paramToJson(value)); }

void hashParamValue(Hasher& h, const ParamValue& value) {
  h.add(static_cast<std::int64_t>(value.index()));
  std::visit(
      [&h](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, Vec3Param>) {
          for (double c : v) h.add(c);
        } else if constexpr (std::is_same_v<V, std::vector<Vec3Param>>) {
          h.add(static_cast<std::uint64_t>(v.size()));
          for (const auto& p : v)
            for (double c : p) h.add(c);
        } else if constexpr (std::is_same_v<V, std::vector<double>> ||
                             std::is_same_v<V, std::vector<std::string>>) {
          h.add(static_cast<std::uint64_t>(v.size()));
          for (const auto& c : v) h.add(c);
        } else {
          h.add(v);
        }
      },
      value);
}

namespace detail {
void unknownChoice(std::string_view name) {
  throw GraphError("\"" + std::string(name) + "\" is not one of the declared choices");
}
std::int64_t paramAsInt64(const ParamValue& v) { return std::get<std::int64_t>(v); }
int paramAsInt(const ParamValue& v) {
  std::int64_t x = std::get<std::int64_t>(v);
  if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
    throw GraphError("integer parameter value " + std::to_string(x) + " does not fit in an int");
  return static_cast<int>(x);
}
}  // namespace detail

}  // namespace tfd::graph
