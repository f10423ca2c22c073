#pragma once
// Graph file format versions and the chain of pure JSON -> JSON migrations v(n) -> v(n+1).
// History (docs/file-format.md has the details):
//   1  editor positions in a top-level "layout" object {"node": [x, y]}
//   2  editor data per node in "ui" ({"position": [x, y], ...}); "layout" removed
#include <string>

#include "graph/json_fwd.h"

namespace tfd::graph {

inline constexpr int kGraphFormatVersion = 2;
inline constexpr const char* kGraphFormatName = "tfd-graph";

/// Checks "format" and "formatVersion" (a missing version is an error, a newer one is refused)
/// and migrates `doc` to kGraphFormatVersion. Throws LoadError(source, pointer, message).
/// `originalVersion`, when given, receives the version found in the file.
Json migrateGraphDocument(Json doc, const std::string& source, int* originalVersion = nullptr);

namespace migrations {
/// Version 1 -> 2: moves each "layout" entry into the node's "ui" as "position".
Json v1ToV2(Json doc, const std::string& source);
}  // namespace migrations

}  // namespace tfd::graph
