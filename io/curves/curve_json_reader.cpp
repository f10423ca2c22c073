#include "io/curves/curve_json_reader.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "io/file_bytes.h"
#include "io/text_scanner.h"

namespace tfd::io {

namespace {

using Json = nlohmann::json;

/// Reports problems at JSON pointers of one file.
struct Where {
  std::string file;
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw core::Error("curve file '" + file + "'" + (pointer.empty() ? "" : " at " + pointer) +
                      ": " + message);
  }
};

/// A short printable rendering of a JSON value for "found ..." messages.
std::string found(const Json& v) {
  std::string text = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 40) + "...";
  return printableText(text);
}

const Json& member(const Json& object, const char* key, const std::string& pointer,
                   const Where& where) {
  const auto it = object.find(key);
  if (it == object.end()) where.fail(pointer, std::string("missing key \"") + key + "\"");
  return *it;
}

int integer(const Json& v, const std::string& pointer, const Where& where) {
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 2147483647)
    where.fail(pointer, "expected a non-negative integer, found " + found(v));
  return static_cast<int>(v.get<long long>());
}

core::Vec3 point(const Json& v, const std::string& pointer, const Where& where) {
  bool ok = v.is_array() && v.size() == 3;
  core::Vec3 p = core::Vec3::Zero();
  for (int k = 0; ok && k < 3; ++k) {
    ok = v[k].is_number() && std::isfinite(v[k].get<double>());
    if (ok) p[k] = v[k].get<double>();
  }
  if (!ok) where.fail(pointer, "expected [x, y, z] with 3 finite numbers, found " + found(v));
  return p;
}

core::DegeneratePattern pattern(const Json& v, const std::string& pointer, const Where& where) {
  for (auto p : {core::DegeneratePattern::Wedge, core::DegeneratePattern::Trisector,
                 core::DegeneratePattern::Transition})
    if (v.is_string() && v.get<std::string>() == core::toString(p)) return p;
  where.fail(pointer, "expected \"wedge\", \"trisector\" or \"transition\", found " + found(v));
}

CurveFileEntry curve(const Json& c, const std::string& at, const Where& where) {
  if (!c.is_object()) where.fail(at, "expected a curve object, found " + found(c));
  CurveFileEntry out;
  out.id = integer(member(c, "id", at, where), at + "/id", where);
  const Json& type = member(c, "type", at, where);
  if (type == "linear" || type == "planar") {
    out.type = type == "linear" ? core::DegenerateType::Linear : core::DegenerateType::Planar;
  } else {
    where.fail(at + "/type", "expected \"linear\" or \"planar\", found " + found(type));
  }
  const Json& closed = member(c, "closed", at, where);
  if (!closed.is_boolean())
    where.fail(at + "/closed", "expected true or false, found " + found(closed));
  out.closed = closed.get<bool>();
  const Json& points = member(c, "points", at, where);
  if (!points.is_array()) where.fail(at + "/points", "expected an array, found " + found(points));
  for (std::size_t i = 0; i < points.size(); ++i)
    out.points.push_back(point(points[i], at + "/points/" + std::to_string(i), where));
  const Json& patterns = member(c, "pattern", at, where);
  if (!patterns.is_array() || patterns.size() != points.size())
    where.fail(at + "/pattern", "expected an array of " + std::to_string(points.size()) +
                                    " patterns (one per point), found " + found(patterns));
  for (std::size_t i = 0; i < patterns.size(); ++i)
    out.patterns.push_back(pattern(patterns[i], at + "/pattern/" + std::to_string(i), where));
  return out;
}

}  // namespace

CurveFile readCurvesJson(const std::filesystem::path& path) {
  const Where where{path.string()};
  const std::string text = readFileBytes(path);
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::exception& e) {
    where.fail("", "invalid JSON: " + printableText(e.what()));
  }
  if (!doc.is_object()) where.fail("", "expected a JSON object, found " + found(doc));
  const Json& format = member(doc, "format", "", where);
  if (format != "tfd-degenerate-curves")
    where.fail("/format", "not a tfd-degenerate-curves file (\"format\" is " + found(format) + ")");
  CurveFile out;
  out.formatVersion = integer(member(doc, "formatVersion", "", where), "/formatVersion", where);
  if (out.formatVersion != 1)
    where.fail("/formatVersion", "version " + std::to_string(out.formatVersion) +
                                     " is not supported (this tfd reads version 1)");
  const Json& curves = member(doc, "curves", "", where);
  if (!curves.is_array()) where.fail("/curves", "expected an array, found " + found(curves));
  for (std::size_t i = 0; i < curves.size(); ++i)
    out.curves.push_back(curve(curves[i], "/curves/" + std::to_string(i), where));
  return out;
}

}  // namespace tfd::io
