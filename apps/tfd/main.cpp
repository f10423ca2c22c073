// tfd — the tensor field designer's command line. Thin: builds the node registry, wires the
// subcommands (one file each) to CLI11 and maps usage errors to exit code 2.
#include <csignal>
#include <iostream>

#include "apps/tfd/cli.h"
#include "apps/tfd/huge_pages.h"
#include "graph/version.h"
#include "nodes/register_all.h"

int main(int argc, char** argv) {
  using namespace tfd;
  cli::restartWithHugePages(argv);
  // A file-size limit (ulimit -f) must fail the write that hits it (EFBIG), which the writers
  // report naming the file, instead of killing the process and leaving a temporary behind.
  std::signal(SIGXFSZ, SIG_IGN);
  graph::NodeRegistry registry;
  try {
    nodes::registerAll(registry);
  } catch (const std::exception& e) {
    cli::printError(std::string("internal error while registering node types: ") + e.what());
    return cli::kUsage;
  }
  const cli::Context context{registry};

  CLI::App app{"tfd — design 3D tensor fields with node graphs (Palacios et al. 2017).", "tfd"};
  app.set_version_flag("--version", std::string("tfd ") + graph::toolVersion());
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 a node failed, 2 usage or load error.");
  int exitCode = cli::kOk;
  cli::addCookCommand(app, context, exitCode);
  cli::addValidateCommand(app, context, exitCode);
  cli::addNodesCommand(app, context, exitCode);
  cli::addInfoCommand(app, context, exitCode);
  cli::addUpgradeCommand(app, context, exitCode);
  cli::addRenderCommand(app, context, exitCode);
  // CLI11 calls an unknown first word an unexpected argument; say what it is and what exists.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    std::string names;
    bool known = false;
    const CLI::App& commands = app;
    for (const CLI::App* sub : commands.get_subcommands([](const CLI::App*) { return true; })) {
      known = known || sub->check_name(word);
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      cli::printError("unknown command \"" + word + "\" (commands: " + names + ")");
      std::cerr << "Run 'tfd --help' for usage.\n";
      return cli::kUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    cli::printError(e.what());
    std::cerr << "Run 'tfd --help' or 'tfd <command> --help' for usage.\n";
    return cli::kUsage;
  }
  return exitCode;
}
