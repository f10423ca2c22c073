// tfd validate GRAPH [--quiet]: loads the graph (every load check) and reports what would stop
// a cook: required inputs without a link (error), input files that do not exist (warning).
#include <iostream>

#include "apps/tfd/cli.h"
#include "graph/format_migrations.h"
#include "graph/paths.h"
#include "graph/validation.h"

namespace tfd::cli {

namespace {

struct ValidateArgs {
  std::string graph;
  bool quiet = false;
};

int runValidate(const ValidateArgs& args, const Context& context) {
  std::optional<graph::Graph> g = loadGraphOrReport(args.graph, context.registry);
  if (!g) return kUsage;
  const auto issues = graph::validateGraph(*g, graph::makePathContext(*g));
  int errors = 0;
  for (const graph::Issue& issue : issues) {
    const bool error = issue.severity == graph::Severity::Error;
    errors += error;
    if (error || !args.quiet)
      std::cerr << "tfd: " << (error ? "" : "warning: ") << args.graph << " at " << issue.pointer
                << ": " << issue.message << "\n";
  }
  if (errors > 0) return kUsage;
  if (!args.quiet) {
    std::cout << "ok: " << args.graph << ": " << g->nodeCount() << " nodes, " << g->links().size()
              << " links, format version " << g->loadedFormatVersion();
    if (g->loadedFormatVersion() < graph::kGraphFormatVersion)
      std::cout << " (current is " << graph::kGraphFormatVersion << "; 'tfd upgrade' rewrites it)";
    std::cout << "\n";
  }
  return kOk;
}

}  // namespace

void addValidateCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand("validate", "Check a graph file without cooking it.");
  cmd->add_option("graph", args->graph, "The graph file (*.tfd.json).")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors.");
  cmd->callback([args, &context, &exitCode] { exitCode = runValidate(*args, context); });
}

}  // namespace tfd::cli
