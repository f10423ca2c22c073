#pragma once
// Shared pieces of the `tfd` command line: exit codes, the node registry, error printing and
// the subcommand entry points (one file per subcommand). main.cpp only wires them to CLI11.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "graph/graph.h"
#include "graph/node_registry.h"

namespace tfd::cli {

/// Exit codes (CONVENTIONS.md "CLI").
enum Exit : int { kOk = 0, kNodeFailed = 1, kUsage = 2 };

/// What every subcommand gets.
struct Context {
  const graph::NodeRegistry& registry;
};

/// Prints "tfd: <message>" on stderr.
void printError(const std::string& message);
/// Loads a graph file; on failure prints the error ("tfd: <file> at <pointer>: <message>") and
/// returns nothing.
std::optional<graph::Graph> loadGraphOrReport(const std::filesystem::path& path,
                                              const graph::NodeRegistry& registry);
/// loadGraphOrReport, then each `--set NODE.PARAM=VALUE` override in order; a bad override is
/// reported like a load error (nothing returned).
std::optional<graph::Graph> loadGraphWithOverrides(const std::filesystem::path& path,
                                                   const graph::NodeRegistry& registry,
                                                   const std::vector<std::string>& sets);

/// Adds `--max-memory SIZE` (core::setMemoryBudget) to a subcommand that reads or computes.
void addMaxMemoryOption(CLI::App& cmd);

// Subcommands: each adds itself to the app and runs from the callback it registers, storing
// its exit code in `exitCode`.
void addCookCommand(CLI::App& app, const Context& context, int& exitCode);
void addValidateCommand(CLI::App& app, const Context& context, int& exitCode);
void addNodesCommand(CLI::App& app, const Context& context, int& exitCode);
void addInfoCommand(CLI::App& app, const Context& context, int& exitCode);
void addUpgradeCommand(CLI::App& app, const Context& context, int& exitCode);
void addRenderCommand(CLI::App& app, const Context& context, int& exitCode);

}  // namespace tfd::cli
