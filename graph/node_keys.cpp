#include "graph/node_keys.h"

#include <filesystem>
#include <system_error>

#include "graph/topology.h"

namespace tfd::graph {

namespace {

void hashFileStamp(Hasher& h, const std::string& path) {
  std::error_code ec;
  auto size = std::filesystem::file_size(path, ec);
  if (ec) {
    h.add("missing");
    return;
  }
  auto time = std::filesystem::last_write_time(path, ec);
  h.add(static_cast<std::uint64_t>(size));
  h.add(static_cast<std::int64_t>(ec ? 0 : time.time_since_epoch().count()));
}

Hash keyOf(const Graph& graph, int index, const std::vector<Hash>& keys,
           const std::vector<std::vector<Link>>& incoming, const KeyOptions& options) {
  const Node& node = graph.nodes()[index];
  const NodeDecl& decl = node.decl();
  Hasher h;
  h.add("tfd-node").add(decl.typeName()).add(decl.typeVersion());
  const std::vector<ParamValue> params = resolvedParams(node, options.paths);
  for (std::size_t i = 0; i < params.size(); ++i) {
    h.add(decl.params()[i].name);
    hashParamValue(h, params[i]);
    if (options.hashInputFileStamps && decl.params()[i].isInputFile())
      hashFileStamp(h, std::get<std::string>(params[i]));
  }
  for (std::size_t k = 0; k < decl.inputs().size(); ++k) {
    h.add(decl.inputs()[k].name);
    const std::vector<Link>& links = incoming[k];
    h.add(static_cast<std::uint64_t>(links.size()));
    for (const Link& l : links) {
      h.add(keys[graph.nodeIndex(l.from.node)]);
      h.add(l.from.port);
    }
  }
  return h.finish();
}

}  // namespace

std::vector<Hash> computeNodeKeys(const Graph& graph, const KeyOptions& options) {
  std::vector<Hash> keys(graph.nodeCount());
  const auto incoming = incomingLinks(graph);
  for (int i : topologicalOrder(graph)) keys[i] = keyOf(graph, i, keys, incoming[i], options);
  return keys;
}

Hash nodeKey(const Graph& graph, std::string_view node, const KeyOptions& options) {
  int index = graph.nodeIndex(node);
  (void)graph.node(node);  // throws for an unknown node
  return computeNodeKeys(graph, options)[index];
}

Hash outputHash(const Hash& nodeKey, std::string_view port) {
  return Hasher().add("tfd-output").add(nodeKey).add(port).finish();
}

}  // namespace tfd::graph
