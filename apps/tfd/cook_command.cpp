// tfd cook GRAPH [--set NODE.PARAM=VALUE]... [--node NAME]... [--out DIR] [--threads N]
//          [--cache DIR [--cache-size SIZE]] [--progress-interval SECONDS]
//          [--profile] [--files] [--strict] [--quiet]
// Writes the cook manifest (cook_manifest.h) into the output folder.
#include <tbb/global_control.h>

#include <iostream>
#include <memory>

#include "apps/tfd/cli.h"
#include "apps/tfd/console_reporter.h"
#include "apps/tfd/cook_manifest.h"
#include "apps/tfd/cook_report.h"
#include "apps/tfd/stop_signals.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "graph/disk_cache.h"
#include "graph/errors.h"
#include "graph/evaluator.h"
#include "graph/overrides.h"
#include "nodes/value_codecs.h"

namespace tfd::cli {

namespace {

struct CookArgs {
  std::string graph;
  std::vector<std::string> sets;
  std::vector<std::string> targets;
  std::string out;
  int threads = 0;
  std::string cache, cacheSize = "2G";
  double progressInterval = 10;
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

  std::unique_ptr<graph::DiskCache> disk;
  if (!args.cache.empty()) {
    try {
      disk = std::make_unique<graph::DiskCache>(args.cache, core::parseByteSize(args.cacheSize),
                                                nodes::valueCodecs());
    } catch (const std::exception& e) {
      printError(std::string(e.what()));
      return kUsage;
    }
  }
  const std::filesystem::path outDir = !args.out.empty() ? std::filesystem::path(args.out)
                                       : std::filesystem::path(args.graph).parent_path().empty()
                                           ? std::filesystem::path(".")
                                           : std::filesystem::path(args.graph).parent_path();
  const ManifestInput manifest{*graph, args.graph, args.sets};
  bool manifestOk = true;
  auto writeManifest = [&](auto&& write) {
    if (!manifestOk) return;
    try {
      write();
    } catch (const std::exception& e) {
      manifestOk = false;
      printError(std::string("warning: cannot write the cook manifest: ") + e.what());
    }
  };
  writeManifest([&] { writeRunningManifest(outDir, manifest); });

  ConsoleReporter reporter(ConsoleReporter::detect(args.quiet), std::cerr, args.progressInterval);
  graph::CookOptions options;
  options.targets = args.targets;
  options.outDir = args.out;
  options.observer = &reporter;
  options.diskCache = disk.get();
  graph::CookResult result;
  int stopSignal = 0;
  // SIGINT, SIGTERM, SIGHUP cancel the cook; a second one stops at once, removing
  // temporaries. Held until the command returns, so a second signal while the manifest and
  // report are written still cleans up (restored defaults there would kill tfd mid-write).
  StopSignals signals;
  options.cancel = &StopSignals::cancelFlag();
  try {
    graph::Evaluator evaluator;
    result = evaluator.cook(*graph, options);
    stopSignal = StopSignals::received();
  } catch (const std::exception& e) {
    reporter.finish();
    writeManifest([&] { writeFinalManifest(outDir, manifest, result, false, e.what()); });
    printError(e.what());
    return kUsage;
  }
  reporter.finish();
  writeManifest([&] { writeFinalManifest(outDir, manifest, result, stopSignal != 0); });
  if (disk && !args.quiet)
    for (const std::string& warning : disk->warnings()) printError("warning: cache: " + warning);
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
  cmd->add_option("--cache", args->cache,
                  "On-disk cook cache: keep each cooked mesh, field and curve set in DIR, keyed "
                  "by the node's content hash, and take unchanged nodes from there in later "
                  "cooks (created if missing; damaged entries are cooked again).")
      ->type_name("DIR");
  cmd->add_option("--cache-size", args->cacheSize,
                  "Size budget of --cache, e.g. 500M (default 2G): least recently used entries "
                  "are removed beyond it.")
      ->type_name("SIZE")
      ->check([](const std::string& text) {
        try {
          core::parseByteSize(text);
          return std::string();
        } catch (const core::Error& e) {
          return std::string(e.what());
        }
      });
  cmd->add_option("--progress-interval", args->progressInterval,
                  "Without a terminal: seconds between the progress lines of a node still "
                  "running (default 10).")
      ->type_name("SECONDS")
      ->check(CLI::Range(0.01, 86400.0));
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
