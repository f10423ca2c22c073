#include "graph/format_migrations.h"

#include <nlohmann/json.hpp>

#include "graph/errors.h"
#include "graph/json_text.h"
#include "graph/version.h"

namespace tfd::graph {

namespace {
using Migration = Json (*)(Json, const std::string&);
// kChain[i] migrates version i + 1 to i + 2.
constexpr Migration kChain[] = {&migrations::v1ToV2};
static_assert(std::size(kChain) == kGraphFormatVersion - 1, "one migration per version step");
}  // namespace

Json migrateGraphDocument(Json doc, const std::string& source, int* originalVersion) {
  if (!doc.is_object())
    throw LoadError(
        source, "",
        "expected a JSON object with \"format\": \"tfd-graph\", found " + describeJson(doc));
  if (!doc.contains("format"))
    throw LoadError(source, "/format",
                    "missing; expected \"format\": \"tfd-graph\" (is this a tfd graph file?)");
  if (doc["format"] != kGraphFormatName)
    throw LoadError(source, "/format",
                    "expected \"tfd-graph\", found " + describeJson(doc["format"]));
  if (!doc.contains("formatVersion"))
    throw LoadError(source, "/formatVersion",
                    "missing; a graph file must state its format version (this tfd writes " +
                        std::to_string(kGraphFormatVersion) + ")");
  const Json& v = doc["formatVersion"];
  if (!v.is_number_integer())
    throw LoadError(source, "/formatVersion", "expected an integer, found " + describeJson(v));
  const long long version = v.get<long long>();
  if (version > kGraphFormatVersion)
    throw LoadError(source, "/formatVersion",
                    "format version " + std::to_string(version) + " is newer than this tfd (" +
                        toolVersion() + ") reads (up to " + std::to_string(kGraphFormatVersion) +
                        "); use a newer tfd");
  if (version < 1)
    throw LoadError(source, "/formatVersion",
                    "expected a format version from 1 to " + std::to_string(kGraphFormatVersion) +
                        ", found " + std::to_string(version));
  if (originalVersion) *originalVersion = static_cast<int>(version);
  for (long long from = version; from < kGraphFormatVersion; ++from) {
    doc = kChain[from - 1](std::move(doc), source);
    doc["formatVersion"] = from + 1;
  }
  return doc;
}

}  // namespace tfd::graph
