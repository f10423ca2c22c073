#pragma once
// Parameters of node types: kinds, declarations (default, range, choices, documentation, UI
// hint) and values. The declaration is the single source for validation, the CLI reference
// (`tfd nodes`), an editor's parameter panel and the cache key.
//
// Kinds and their JSON form:
//   bool        true / false
//   int         integer (stored as int64)
//   double      number
//   string      string; with choices it is an enum; with an InputFile/OutputFile hint a path
//               (relative paths resolve against the graph file's folder, outputs against --out)
//   vec3        [x, y, z]
//   vec3 list   [[x, y, z], ...]
//   double list [a, b, ...] (optionally of a fixed size, e.g. 6 tensor components)
//   string list ["a", "b", ...]; with choices, each element is one of them (a set of options)
// min/max are inclusive and apply to int, double and every component of vec3 and lists.
//
// Enum parameters are strings with choices. Their string table is declared once, in the node
// file, as a Choices<E> that maps each string to the core enum: the declaration takes the names
// (`.choices(kShapes)`) and the cook the enum (`c.param("primitive", kShapes)`), so core only
// ever sees enums.
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "graph/json_fwd.h"

namespace tfd::graph {

class Hasher;

using Vec3Param = std::array<double, 3>;

enum class ParamKind { Bool, Int, Double, String, Vec3, Vec3List, DoubleList, StringList };

/// How an editor should present a parameter. InputFile / OutputFile also select how the engine
/// resolves relative paths.
enum class UiHint {
  Auto,
  Slider,
  LogSlider,
  Angle,
  Position,
  Direction,
  InputFile,
  OutputFile,
  Multiline
};

/// Alternative index == static_cast<int>(ParamKind).
using ParamValue =
    std::variant<bool, std::int64_t, double, std::string, Vec3Param, std::vector<Vec3Param>,
                 std::vector<double>, std::vector<std::string>>;

struct ParamDecl {
  std::string name;
  ParamKind kind = ParamKind::Double;
  ParamValue defaultValue;
  std::optional<double> min, max;    ///< inclusive
  std::vector<std::string> choices;  ///< string (an enum) and string list: the allowed values
  std::optional<std::size_t> size;   ///< double list: exact number of values
  std::size_t minSize = 0;           ///< lists: fewest elements
  std::string doc;                   ///< one or two sentences for `tfd nodes` and tooltips
  std::string label;                 ///< display label; empty: derived from the name
  UiHint hint = UiHint::Auto;
  std::string fileFilter;  ///< file hints: e.g. "*.obj *.ply *.off"
  /// Optional check beyond kind, range, choices and size (e.g. that an expression parses):
  /// throws std::exception whose message says what is wrong. Runs in checkParamValue, so
  /// Graph::setParam, file loading and an editor's as-you-type validation all use it.
  std::function<void(const ParamValue&)> check;

  bool isInputFile() const { return hint == UiHint::InputFile; }
  bool isOutputFile() const { return hint == UiHint::OutputFile; }
  bool isPath() const { return isInputFile() || isOutputFile(); }
  /// "Boundary conforming" for "boundary_conforming" unless a label was given.
  std::string displayLabel() const;
};

std::string_view kindName(ParamKind kind);  ///< "bool", "int", "double", "string", ...
std::string_view hintName(UiHint hint);     ///< "auto", "slider", "input-file", ...
/// What a user sees as the type: "bool", "int", "double", "string", "enum", "input file",
/// "output file", "vec3", "vec3 list", "double[6]", "double list".
std::string typeLabel(const ParamDecl& decl);
/// "a number in [0, 1]", "one of \"sphere\", \"box\"", "an array of 3 numbers [x, y, z]"...
std::string describeExpected(const ParamDecl& decl);
/// Range/choices summary for docs: "[0, 1]", ">= 1e-14", "sphere | box", "" when unconstrained.
std::string describeConstraints(const ParamDecl& decl);

/// Converts a value to the declared kind (int -> double) and checks kind, range, choices and
/// sizes, then runs the declaration's `check`. Throws GraphError("expected <...>, found <...>",
/// or the check's message) without naming node or parameter.
ParamValue checkParamValue(const ParamDecl& decl, ParamValue value);
/// Parses the JSON form; same checks and errors as checkParamValue.
ParamValue paramFromJson(const ParamDecl& decl, const Json& json);
Json paramToJson(const ParamValue& value);
/// Parses command-line text (`--set node.param=TEXT`): plain text for strings and enums,
/// true/false/1/0/yes/no/on/off for bools, numbers for int/double, JSON for vectors and lists
/// (brackets may be left out for a vec3 or double list: "0.1,0,0").
ParamValue paramFromText(const ParamDecl& decl, std::string_view text);
/// Compact JSON text of a value, e.g. `[0.1, 0.0, 0.0]`, `"sphere"`, `true`.
std::string formatParamValue(const ParamValue& value);
void hashParamValue(Hasher& hasher, const ParamValue& value);

namespace detail {
[[noreturn]] void unknownChoice(std::string_view name);
}  // namespace detail

/// The string table of an enum parameter: each allowed string with its enum value, in the order
/// users see them (the first is the default unless the declaration says otherwise).
template <class E>
class Choices {
 public:
  Choices(std::initializer_list<std::pair<const char*, E>> entries)
      : entries_(entries.begin(), entries.end()) {}
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [name, value] : entries_) out.emplace_back(name);
    return out;
  }
  /// The enum of a validated string; throws GraphError for a string not in the table.
  E value(std::string_view name) const {
    for (const auto& [n, v] : entries_)
      if (name == n) return v;
    detail::unknownChoice(name);
  }
  /// The string of an enum value (the first listed when several map to it).
  const char* name(E value) const {
    for (const auto& [n, v] : entries_)
      if (v == value) return n;
    return "";
  }

 private:
  std::vector<std::pair<const char*, E>> entries_;
};

/// Maps a C++ type to a parameter kind for NodeDecl::param<T> and CookContext::param<T>.
/// Supported: bool, int, std::int64_t, double, std::string, Vec3Param,
/// std::vector<Vec3Param>, std::vector<double>, std::vector<std::string>.
template <class T>
struct ParamTraits;

namespace detail {
std::int64_t paramAsInt64(const ParamValue& v);
int paramAsInt(const ParamValue& v);  // throws GraphError when out of int range
}  // namespace detail

template <>
struct ParamTraits<bool> {
  static constexpr ParamKind kind = ParamKind::Bool;
  static ParamValue toValue(bool v) { return v; }
  static bool fromValue(const ParamValue& v) { return std::get<bool>(v); }
};
template <>
struct ParamTraits<int> {
  static constexpr ParamKind kind = ParamKind::Int;
  static ParamValue toValue(int v) { return static_cast<std::int64_t>(v); }
  static int fromValue(const ParamValue& v) { return detail::paramAsInt(v); }
};
template <>
struct ParamTraits<std::int64_t> {
  static constexpr ParamKind kind = ParamKind::Int;
  static ParamValue toValue(std::int64_t v) { return v; }
  static std::int64_t fromValue(const ParamValue& v) { return detail::paramAsInt64(v); }
};
template <>
struct ParamTraits<double> {
  static constexpr ParamKind kind = ParamKind::Double;
  static ParamValue toValue(double v) { return v; }
  static double fromValue(const ParamValue& v) { return std::get<double>(v); }
};
template <>
struct ParamTraits<std::string> {
  static constexpr ParamKind kind = ParamKind::String;
  static ParamValue toValue(std::string v) { return v; }
  static std::string fromValue(const ParamValue& v) { return std::get<std::string>(v); }
};
template <>
struct ParamTraits<Vec3Param> {
  static constexpr ParamKind kind = ParamKind::Vec3;
  static ParamValue toValue(const Vec3Param& v) { return v; }
  static Vec3Param fromValue(const ParamValue& v) { return std::get<Vec3Param>(v); }
};
template <>
struct ParamTraits<std::vector<Vec3Param>> {
  static constexpr ParamKind kind = ParamKind::Vec3List;
  static ParamValue toValue(std::vector<Vec3Param> v) { return v; }
  static std::vector<Vec3Param> fromValue(const ParamValue& v) {
    return std::get<std::vector<Vec3Param>>(v);
  }
};
template <>
struct ParamTraits<std::vector<double>> {
  static constexpr ParamKind kind = ParamKind::DoubleList;
  static ParamValue toValue(std::vector<double> v) { return v; }
  static std::vector<double> fromValue(const ParamValue& v) {
    return std::get<std::vector<double>>(v);
  }
};

template <>
struct ParamTraits<std::vector<std::string>> {
  static constexpr ParamKind kind = ParamKind::StringList;
  static ParamValue toValue(std::vector<std::string> v) { return v; }
  static std::vector<std::string> fromValue(const ParamValue& v) {
    return std::get<std::vector<std::string>>(v);
  }
};

}  // namespace tfd::graph
