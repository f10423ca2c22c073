#pragma once
namespace tfd::graph {
/// The tool's semantic version, written into saved graphs as "generator": "tfd <version>".
const char* toolVersion();
}  // namespace tfd::graph
