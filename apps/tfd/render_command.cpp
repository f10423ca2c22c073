// tfd render GRAPH [--node NAME] [--view iso|x|y|z] [--size WxH] [--slice AXIS[=POS]]
//            [--quantity mode|degeneracy|norm] [--set NODE.PARAM=VALUE]... -o OUT.png
// Cooks what the node needs (no exporter runs) and draws its output with the editor's render/
// code into a PNG, through a surfaceless EGL context: no X server or display needed.
#include <iostream>
#include <memory>
#include <regex>

#include "apps/tfd/cli.h"
#include "apps/tfd/console_reporter.h"
#include "apps/tfd/cook_report.h"
#include "graph/errors.h"
#include "graph/evaluator.h"
#include "graph/overrides.h"
#include "nodes/display_values.h"
#include "render/headless.h"
#include "render/scene_builder.h"

namespace tfd::cli {

namespace {

struct RenderArgs {
  std::string graph, node, view = "iso", size = "1024x768", slice, quantity = "mode", out;
  std::vector<std::string> sets;
  bool quiet = false;
};

/// "WxH" -> sizes, or nothing.
std::optional<std::pair<int, int>> parseSize(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,5})x(\d{1,5}))"))) return std::nullopt;
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 16 || h < 16 || w > 8192 || h > 8192) return std::nullopt;
  return std::make_pair(w, h);
}

/// "z", "x=0.3" -> slice settings, or nothing.
std::optional<render::SliceSettings> parseSlice(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"(([xyz])(?:=([0-9]*\.?[0-9]+))?)")))
    return std::nullopt;
  render::SliceSettings s;
  s.axis = m[1].str()[0] - 'x';
  if (m[2].matched) s.position = std::stod(m[2]);
  if (s.position < 0 || s.position > 1) return std::nullopt;
  return s;
}

/// The targets that produce what `node` shows: itself, or for a sink what is linked into it.
std::vector<std::string> targetsFor(const graph::Graph& g, const std::string& node) {
  if (!g.node(node).decl().isSink()) return {node};
  std::vector<std::string> out;
  for (const graph::Link& l : g.links())
    if (l.to.node == node && std::find(out.begin(), out.end(), l.from.node) == out.end())
      out.push_back(l.from.node);
  return out;
}

int runRender(const RenderArgs& args, const Context& context) {
  std::optional<graph::Graph> graph =
      loadGraphWithOverrides(args.graph, context.registry, args.sets);
  if (!graph) return kUsage;
  const std::string node = args.node.empty() ? nodes::displayNodeName(*graph) : args.node;
  if (node.empty()) {
    printError(args.graph + ": the graph has no nodes to draw");
    return kUsage;
  }
  if (!graph->findNode(node)) {
    printError("--node " + node + ": unknown node \"" + node + "\"");
    return kUsage;
  }
  const auto view = render::parseViewPreset(args.view);
  const auto size = parseSize(args.size);
  const auto quantity = render::parseSliceQuantity(args.quantity);
  std::optional<render::SliceSettings> slice;
  if (!args.slice.empty() && !(slice = parseSlice(args.slice))) {
    printError("--slice " + args.slice + ": expected x, y or z, optionally =POSITION in [0, 1]");
    return kUsage;
  }
  if (!view || !size || !quantity) {
    printError(!view   ? "--view " + args.view + ": expected iso, x, y or z"
               : !size ? "--size " + args.size + ": expected WIDTHxHEIGHT, each in 16..8192"
                       : "--quantity " + args.quantity + ": expected mode, degeneracy or norm");
    return kUsage;
  }
  if (slice) slice->quantity = *quantity;

  ConsoleReporter reporter(ConsoleReporter::detect(args.quiet));
  graph::CookOptions options;
  options.targets = targetsFor(*graph, node);
  options.observer = &reporter;
  graph::Evaluator evaluator;
  graph::CookResult result = evaluator.cook(*graph, options);
  reporter.finish();
  if (!result.ok())
    return printCookReport(result, {args.quiet, false, false}, std::cout, std::cerr);

  const nodes::DisplayValues values = nodes::displayValues(*graph, result, node);
  if (values.empty()) {
    printError("node \"" + node + "\" (" + graph->node(node).type().name() +
               ") has nothing to draw (no mesh, field, curves, lines or design elements)");
    return kNodeFailed;
  }
  render::SceneInput in;
  in.mesh = values.mesh.get();
  in.field = values.field.get();
  in.curves = values.curves.get();
  in.lines = values.lines.get();
  for (const auto& c : values.constraints) in.constraints.push_back(c.get());
  if (slice && !values.field) {
    printError("--slice: node \"" + node + "\" shows no tensor field to cut");
    return kUsage;
  }
  in.slice = slice;
  try {
    render::RenderRequest request;
    request.width = size->first;
    request.height = size->second;
    request.view = *view;
    render::writePng(render::renderImage(render::buildScene(in), request), args.out);
  } catch (const std::exception& e) {
    printError(e.what());
    return kNodeFailed;
  }
  if (!args.quiet) std::cerr << "tfd: drew node \"" << node << "\" to " << args.out << "\n";
  return kOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Draw a node's output (boundary, curves, design elements, a cut) to a PNG, "
      "without a display.");
  cmd->add_option("graph", args->graph, "The graph file (*.tfd.json).")->required();
  cmd->add_option("--node", args->node,
                  "The node to draw (default: the editor's display node, else the last node "
                  "with outputs).")
      ->type_name("NAME");
  cmd->add_option("--view", args->view, "iso (default), or along x, y or z.")->type_name("VIEW");
  cmd->add_option("--size", args->size, "Picture size (default 1024x768).")->type_name("WxH");
  cmd->add_option("--slice", args->slice,
                  "Add a cutting plane across an axis, at a fraction of the extent "
                  "(e.g. z or x=0.3).")
      ->type_name("AXIS[=POS]");
  cmd->add_option("--quantity", args->quantity,
                  "What the cutting plane shows: mode (default), degeneracy or norm.")
      ->type_name("NAME");
  cmd->add_option("--set", args->sets, "Override a parameter: NODE.PARAM=VALUE. Repeatable.")
      ->type_name("NODE.PARAM=VALUE")
      ->allow_extra_args(false);
  cmd->add_option("-o,--output", args->out, "The PNG file to write.")
      ->required()
      ->type_name("OUT.png");
  addMaxMemoryOption(*cmd);
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors.");
  cmd->callback([args, &context, &exitCode] { exitCode = runRender(*args, context); });
}

}  // namespace tfd::cli
