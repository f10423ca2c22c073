// tfd validate GRAPH... [--json] [--quiet]: loads each graph file collecting every problem
// (unknown node types and keys, bad parameters, bad or type-mismatched links, cycles), then
// checks what would stop a cook: required inputs without a link (error), input files that do
// not exist (warning). Exit 2 when any file has an error.
//
// --json prints one report on stdout (schema documented in README, "Command line"):
//   {"format": "tfd-validate", "formatVersion": 1, "ok": false,
//    "files": [{"file": "a.tfd.json", "ok": false, "formatVersion": 2,
//               "problems": [{"severity": "error", "node": "field", "parameter": "radius",
//                             "pointer": "/nodes/field/params/radius", "message": "..."}]}]}
//   ("node" / "parameter" are null when the problem concerns no node / no parameter;
//    "formatVersion" is null when the file could not be read as a graph.)
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/tfd/cli.h"
#include "graph/format_migrations.h"
#include "graph/graph_file.h"
#include "graph/paths.h"
#include "graph/validation.h"

namespace tfd::cli {

namespace {

using Json = nlohmann::ordered_json;

struct ValidateArgs {
  std::vector<std::string> graphs;
  bool quiet = false, json = false;
};

struct Problem {
  bool error = true;
  std::string node, parameter, pointer, message;
};

/// "/nodes/NAME/params/PARAM" -> PARAM (JSON pointer escapes undone), else "".
std::string parameterOf(const std::string& pointer, const std::string& node) {
  const std::string prefix = "/nodes/";
  if (pointer.rfind(prefix, 0) != 0 || node.empty()) return {};
  const std::size_t at = pointer.find("/params/");
  if (at == std::string::npos) return {};
  std::string name = pointer.substr(at + 8);
  name = name.substr(0, name.find('/'));
  for (std::size_t i; (i = name.find("~1")) != std::string::npos;) name.replace(i, 2, "/");
  for (std::size_t i; (i = name.find("~0")) != std::string::npos;) name.replace(i, 2, "~");
  return name;
}

Json nullable(const std::string& text) { return text.empty() ? Json(nullptr) : Json(text); }

/// Validates one file; prints text lines unless --json; returns its JSON report.
Json validateFile(const std::string& file, const ValidateArgs& args, const Context& context) {
  std::vector<graph::LoadProblem> loadProblems;
  std::optional<graph::Graph> g =
      graph::loadGraphFileCollecting(file, context.registry, loadProblems);
  std::vector<Problem> problems;
  for (const graph::LoadProblem& p : loadProblems)
    problems.push_back({true, p.node, p.parameter, p.pointer, p.message});
  if (g)
    for (const graph::Issue& issue : graph::validateGraph(*g, graph::makePathContext(*g)))
      problems.push_back({issue.severity == graph::Severity::Error, issue.node,
                          parameterOf(issue.pointer, issue.node), issue.pointer, issue.message});
  bool ok = true;
  Json list = Json::array();
  for (const Problem& p : problems) {
    ok = ok && !p.error;
    list.push_back({{"severity", p.error ? "error" : "warning"},
                    {"node", nullable(p.node)},
                    {"parameter", nullable(p.parameter)},
                    {"pointer", p.pointer},
                    {"message", p.message}});
    if (!args.json && (p.error || !args.quiet))
      printError(std::string(p.error ? "" : "warning: ") + file +
                 (p.pointer.empty() ? "" : " at " + p.pointer) + ": " + p.message);
  }
  if (!args.json && !args.quiet && ok) {
    std::cout << "ok: " << file << ": " << g->nodeCount() << " nodes, " << g->links().size()
              << " links, format version " << g->loadedFormatVersion();
    if (g->loadedFormatVersion() < graph::kGraphFormatVersion)
      std::cout << " (current is " << graph::kGraphFormatVersion << "; 'tfd upgrade' rewrites it)";
    std::cout << "\n";
  }
  if (!args.json && !ok && problems.size() > 1)
    printError(file + ": " + std::to_string(problems.size()) + " problems");
  return {{"file", file},
          {"ok", ok},
          {"formatVersion", g ? Json(g->loadedFormatVersion()) : Json(nullptr)},
          {"problems", std::move(list)}};
}

int runValidate(const ValidateArgs& args, const Context& context) {
  Json files = Json::array();
  bool ok = true;
  for (const std::string& file : args.graphs) {
    files.push_back(validateFile(file, args, context));
    ok = ok && files.back()["ok"].get<bool>();
  }
  if (args.json) {
    const Json report = {
        {"format", "tfd-validate"}, {"formatVersion", 1}, {"ok", ok}, {"files", std::move(files)}};
    std::cout << report.dump(2) << "\n";
  }
  return ok ? kOk : kUsage;
}

}  // namespace

void addValidateCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Check graph files without cooking them; reports every problem of each.");
  cmd->add_option("graphs", args->graphs, "The graph files (*.tfd.json).")->required();
  cmd->add_flag("--json", args->json,
                "Print one JSON report on stdout instead of text (see README for the schema).");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors.");
  cmd->callback([args, &context, &exitCode] { exitCode = runValidate(*args, context); });
}

}  // namespace tfd::cli
