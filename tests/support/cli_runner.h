#pragma once
// Runs the built `tfd` binary (TFD_CLI_PATH) for end-to-end CLI tests.
#include <string>

namespace tfd::test {

struct CliRun {
  int exitCode = -1;
  std::string out, err;  ///< stdout and stderr
};

/// True when the tfd binary was built (TFD_CLI_PATH is not empty and exists).
bool cliAvailable();
/// Runs `tfd <args>` through the shell (args are passed verbatim: quote them yourself) in
/// `workingDir` (default: the current directory), capturing stdout and stderr.
CliRun runCli(const std::string& args, const std::string& workingDir = {});
/// Single-quotes a string for the shell.
std::string shellQuote(const std::string& text);

}  // namespace tfd::test
