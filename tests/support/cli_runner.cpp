#include "tests/support/cli_runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tfd::test {

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

bool cliAvailable() {
  const std::string path = TFD_CLI_PATH;
  return !path.empty() && std::filesystem::exists(path);
}

std::string shellQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

CliRun runCli(const std::string& args, const std::string& workingDir) {
  static std::atomic<int> counter{0};
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / ("tfd_cli_run_" + std::to_string(getpid()) +
                                                     "_" + std::to_string(counter++));
  const fs::path out = base.string() + ".out", err = base.string() + ".err";
  std::string command;
  if (!workingDir.empty()) command = "cd " + shellQuote(workingDir) + " && ";
  command += shellQuote(TFD_CLI_PATH) + " " + args + " >" + shellQuote(out.string()) + " 2>" +
             shellQuote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(out);
  run.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return run;
}

}  // namespace tfd::test
