#pragma once
// The cook manifest `tfd-cook.json`, written into the output folder so the files of one cook
// can be told apart from older ones. Written atomically (temporary file + rename): once with
// status "running" before anything cooks (an interrupted cook never leaves an older
// "complete" behind), and again at the end with the final status.
//
//   {
//     "format": "tfd-cook", "formatVersion": 1, "generator": "tfd 0.1.0",
//     "graph": {"path": "default.tfd.json", "hash": "<32 hex>", "sets": ["vtu.path=a.vtu"]},
//     "status": "running" | "complete" | "cancelled" | "failed",
//     "failed": [{"node": "field", "type": "Propagate", "message": "..."}],  // status failed
//     "nodes": [{"node": "ball", "type": "TetMesh", "key": "<32 hex>",
//                "state": "cooked" | "cached" | "cached (disk)" | "failed" | ...}],
//     "files": [{"node": "vtu", "path": "/out/default.vtu", "size": 123456,
//                "written": true}]   // false: kept from an earlier cook (cached, unchanged)
//   }
//
// "hash" is the content hash of the graph as cooked (the file plus the --set overrides, in
// canonical form); "key" is each node's cache key (graph/node_keys.h).
#include <filesystem>
#include <string>
#include <vector>

#include "graph/evaluator.h"
#include "graph/graph.h"

namespace tfd::cli {

inline constexpr const char* kManifestName = "tfd-cook.json";

struct ManifestInput {
  const graph::Graph& graph;
  std::string graphPath;
  std::vector<std::string> sets;
};

/// Status "running", before the cook. Throws GraphError when it cannot be written.
void writeRunningManifest(const std::filesystem::path& dir, const ManifestInput& in);
/// The final manifest: status from the result ("cancelled" when `cancelled`), or "failed"
/// naming `error` when the cook threw.
void writeFinalManifest(const std::filesystem::path& dir, const ManifestInput& in,
                        const graph::CookResult& result, bool cancelled,
                        const std::string& error = {});

}  // namespace tfd::cli
