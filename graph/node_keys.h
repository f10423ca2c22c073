#pragma once
// Cache keys (the "hash" half of Gaffer's hash()/compute()). A node's key hashes its type,
// typeVersion, ALL its parameter values in declaration order (defaults included, file paths
// resolved), for input files their size and modification time (so editing a mesh file
// re-cooks), and for each input port in declaration order the keys and port names of the
// outputs linked into it, in link order. The node's name and editor data are not part of it.
// An output's hash is hash(node key, port name).
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/hash.h"
#include "graph/paths.h"

namespace tfd::graph {

struct KeyOptions {
  PathContext paths;
  bool hashInputFileStamps = true;
};

/// One key per node of graph.nodes(). Cheap: reads no values, only file stamps.
std::vector<Hash> computeNodeKeys(const Graph& graph, const KeyOptions& options);

/// The key of one node (computes its upstream keys).
Hash nodeKey(const Graph& graph, std::string_view node, const KeyOptions& options);

Hash outputHash(const Hash& nodeKey, std::string_view port);

}  // namespace tfd::graph
