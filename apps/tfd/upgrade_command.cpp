// tfd upgrade GRAPH -o NEW: rewrites a graph in the current format (format migrations and
// node-type migrations applied), atomically.
#include <iostream>

#include "apps/tfd/cli.h"
#include "graph/errors.h"
#include "graph/format_migrations.h"
#include "graph/graph_file.h"

namespace tfd::cli {

namespace {

struct UpgradeArgs {
  std::string graph, output;
  bool quiet = false;
};

bool hasRelativeFileParams(const graph::Graph& g) {
  for (const graph::Node& n : g.nodes())
    for (std::size_t i = 0; i < n.decl().params().size(); ++i)
      if (n.decl().params()[i].isPath()) {
        const auto& v = std::get<std::string>(n.paramAt(i));
        if (!v.empty() && std::filesystem::path(v).is_relative()) return true;
      }
  return false;
}

int runUpgrade(const UpgradeArgs& args, const Context& context) {
  std::optional<graph::Graph> g = loadGraphOrReport(args.graph, context.registry);
  if (!g) return kUsage;
  try {
    graph::saveGraphFile(*g, args.output);
  } catch (const graph::GraphError& e) {
    printError(e.what());
    return kUsage;
  }
  namespace fs = std::filesystem;
  const fs::path from = fs::absolute(args.graph).parent_path().lexically_normal();
  const fs::path to = fs::absolute(args.output).parent_path().lexically_normal();
  if (from != to && hasRelativeFileParams(*g) && !args.quiet)
    std::cerr << "tfd: warning: relative file paths are kept as written and now resolve against "
              << to.string() << "\n";
  if (!args.quiet)
    std::cout << "upgraded " << args.graph << " (format version " << g->loadedFormatVersion()
              << ") to " << args.output << " (format version " << graph::kGraphFormatVersion
              << ")\n";
  return kOk;
}

}  // namespace

void addUpgradeCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<UpgradeArgs>();
  CLI::App* cmd = app.add_subcommand("upgrade", "Rewrite a graph file in the current format.");
  cmd->add_option("graph", args->graph, "The graph file to read.")->required();
  cmd->add_option("-o,--output", args->output, "The file to write (may be the same file).")
      ->required()
      ->type_name("NEW");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors.");
  cmd->callback([args, &context, &exitCode] { exitCode = runUpgrade(*args, context); });
}

}  // namespace tfd::cli
