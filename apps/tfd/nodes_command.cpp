// tfd nodes [TYPE] [--markdown | --json]: the node reference, from the registry. The Markdown
// form is committed as docs/nodes.md (a test checks it is up to date).
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/tfd/cli.h"
#include "graph/errors.h"
#include "graph/json_text.h"
#include "graph/node_docs.h"

namespace tfd::cli {

namespace {

struct NodesArgs {
  std::string type;
  bool markdown = false, json = false;
};

int runNodes(const NodesArgs& args, const Context& context) {
  const graph::NodeRegistry& registry = context.registry;
  const graph::NodeType* type = nullptr;
  if (!args.type.empty()) {
    try {
      type = &registry.get(args.type);
    } catch (const graph::GraphError& e) {
      printError(e.what());
      return kUsage;
    }
  }
  if (args.markdown) {
    if (type) {
      printError("--markdown documents every node type; leave out TYPE");
      return kUsage;
    }
    std::cout << graph::nodeTypesMarkdown(registry);
  } else if (args.json) {
    std::cout << graph::formatJson(type ? graph::nodeTypeJson(*type)
                                        : graph::nodeTypesJson(registry));
  } else {
    std::cout << (type ? graph::nodeTypeText(*type) : graph::nodeTypesText(registry));
  }
  return kOk;
}

}  // namespace

void addNodesCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<NodesArgs>();
  CLI::App* cmd = app.add_subcommand("nodes", "List node types, or describe one.");
  cmd->add_option("type", args->type, "A node type, e.g. Propagate.");
  auto* md = cmd->add_flag("--markdown", args->markdown, "Markdown (what docs/nodes.md holds).");
  auto* js = cmd->add_flag("--json", args->json, "JSON, for editors and scripts.");
  md->excludes(js);
  cmd->callback([args, &context, &exitCode] { exitCode = runNodes(*args, context); });
}

}  // namespace tfd::cli
