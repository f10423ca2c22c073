#pragma once
// The JSON type of the graph layer: key order preserved (stable, byte-identical saves).
#include <nlohmann/json_fwd.hpp>

namespace tfd::graph {
using Json = nlohmann::ordered_json;
}
