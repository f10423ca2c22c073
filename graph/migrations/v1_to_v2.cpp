// Graph format 1 -> 2. Version 1 kept every editor position in one top-level object,
//   "layout": {"mesh1": [0, 0], "prop1": [220, 40]}
// and nodes had no "ui" key. Version 2 keeps editor data with its node, apart from params:
//   "nodes": {"mesh1": {..., "ui": {"position": [0, 0]}}}
// Pure JSON -> JSON; node order, key order and everything else are kept.
#include <nlohmann/json.hpp>

#include "graph/errors.h"
#include "graph/format_migrations.h"
#include "graph/json_text.h"

namespace tfd::graph::migrations {

Json v1ToV2(Json doc, const std::string& source) {
  Json layout = Json::object();
  if (doc.contains("layout")) {
    layout = doc["layout"];
    if (!layout.is_object())
      throw LoadError(source, "/layout",
                      "expected an object {\"node\": [x, y]}, found " + describeJson(layout));
    doc.erase("layout");
  }
  Json* nodes = doc.contains("nodes") && doc["nodes"].is_object() ? &doc["nodes"] : nullptr;
  if (nodes) {
    for (auto& [name, node] : nodes->items())
      if (node.is_object() && node.contains("ui"))
        throw LoadError(source, pointerJoin(pointerJoin("/nodes", name), "ui"),
                        "unexpected key \"ui\" in a format version 1 file (version 1 kept "
                        "editor positions in the top-level \"layout\")");
  }
  for (const auto& [name, position] : layout.items()) {
    const std::string where = pointerJoin("/layout", name);
    if (!nodes || !nodes->contains(name) || !(*nodes)[name].is_object())
      throw LoadError(source, where, "layout of an unknown node \"" + name + "\"");
    if (!position.is_array() || position.size() != 2 || !position[0].is_number() ||
        !position[1].is_number())
      throw LoadError(source, where, "expected [x, y], found " + describeJson(position));
    (*nodes)[name]["ui"] = Json{{"position", position}};
  }
  return doc;
}

}  // namespace tfd::graph::migrations
