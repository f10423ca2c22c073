// tfd cook GRAPH [--set NODE.PARAM=VALUE]... [--node NAME]... [--out DIR] [--threads N]
//          [--profile] [--files] [--strict] [--quiet]
#include <tbb/global_control.h>

#include <iostream>
#include <memory>

#include "apps/tfd/cli.h"
#include "apps/tfd/console_reporter.h"
#include "apps/tfd/cook_report.h"
#include "apps/tfd/stop_signals.h"
#include "graph/errors.h"
#include "graph/evaluator.h"
#include "graph/overrides.h"

namespace tfd::cli {

namespace {

struct CookArgs {
  std::string graph;
  std::vector<std::string> sets;
  std::vector<std::string> targets;
  std::string out;
  int threads = 0;
  bool profile = false, files = false, strict = false, quiet = false;
};

int runCook(const CookArgs& args, const Context& context) {
  std::optional<graph::Graph> graph =
      loadGraphWithOverrides(args.graph, context.registry, args.sets);
  if (!graph) return kUsage;
  for (const std::string& target : args.targets)
    if (!graph->findNode(target)) {
      printError("--node " + target + ": unknown node \"" + target + "\"");
      return kUsage;
    }
  if (!args.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (ec) {
      printError("--out " + args.out + ": cannot create the folder: " + ec.message());
      return kUsage;
    }
  }
  std::unique_ptr<tbb::global_control> threads;
  if (args.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<std::size_t>(args.threads));

  ConsoleReporter reporter(ConsoleReporter::detect(args.quiet));
  graph::CookOptions options;
  options.targets = args.targets;
  options.outDir = args.out;
  options.observer = &reporter;
  graph::CookResult result;
  int stopSignal = 0;
  try {
    StopSignals signals;  // SIGINT, SIGTERM, SIGHUP cancel the cook
    options.cancel = &StopSignals::cancelFlag();
    graph::Evaluator evaluator;
    result = evaluator.cook(*graph, options);
    stopSignal = StopSignals::received();
  } catch (const std::exception& e) {
    reporter.finish();
    printError(e.what());
    return kUsage;
  }
  reporter.finish();
  const int code = printCookReport(result, {args.quiet, args.strict, args.profile, args.files},
                                   std::cout, std::cerr);
  return stopSignal != 0 ? 128 + stopSignal : code;
}

}  // namespace

void addCookCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<CookArgs>();
  CLI::App* cmd = app.add_subcommand("cook", "Cook a graph: compute every output and export.");
  cmd->add_option("graph", args->graph, "The graph file (*.tfd.json).")->required();
  cmd->add_option("--set", args->sets,
                  "Override a parameter: NODE.PARAM=VALUE (JSON for vectors: "
                  "p1.position=[0.1,0,0]). Repeatable.")
      ->type_name("NODE.PARAM=VALUE")
      ->allow_extra_args(false);
  cmd->add_option("--node", args->targets,
                  "Cook only this node and what it needs (default: every node whose result is "
                  "not used by another, i.e. all exporters). Repeatable.")
      ->type_name("NAME")
      ->allow_extra_args(false);
  cmd->add_option("--out", args->out,
                  "Folder for relative output paths (default: the graph file's folder); created "
                  "if missing.")
      ->type_name("DIR");
  cmd->add_option("--threads", args->threads, "Use at most N threads.")
      ->type_name("N")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--profile", args->profile,
                "After cooking, print 'profile <node> <type> <seconds>' per cooked node.");
  cmd->add_flag("--files", args->files,
                "After cooking, print 'file <node> <path>' per file the cook wrote.");
  addMaxMemoryOption(*cmd);
  cmd->add_flag("--strict", args->strict, "Treat warnings as errors (exit 1).");
  cmd->add_flag("-q,--quiet", args->quiet,
                "Print nothing but errors (and --profile, --files lines).");
  cmd->callback([args, &context, &exitCode] { exitCode = runCook(*args, context); });
}

}  // namespace tfd::cli
