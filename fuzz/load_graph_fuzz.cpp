// libFuzzer target: graph files (graph/graph_file.h) with every built-in node type, format
// and typeVersion migrations included. Text either fails to load with graph::LoadError, or
// loads into a graph that validates without throwing and whose canonical text round-trips:
// save -> load -> save gives identical text.
#include <string_view>

#include "fuzz/fuzz_support.h"
#include "graph/errors.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "graph/validation.h"
#include "nodes/register_all.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  static const graph::NodeRegistry* registry = [] {
    auto* r = new graph::NodeRegistry;
    nodes::registerAll(*r);
    return r;
  }();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string saved;
  try {
    const graph::Graph g = graph::parseGraph(text, *registry, "input.tfd.json");
    (void)graph::validateGraph(g, graph::makePathContext(g, "/nonexistent", "/nonexistent"));
    saved = graph::graphToText(g);
  } catch (const graph::LoadError& e) {
    fuzz::checkMessage("input.tfd.json", e.what());
    return 0;
  } catch (const std::exception& e) {
    fuzz::finding(std::string("loading threw ") + typeid(e).name() + ": " + e.what());
  }
  try {
    const graph::Graph again = graph::parseGraph(saved, *registry, "saved.tfd.json");
    if (graph::graphToText(again) != saved)
      fuzz::finding("save -> load -> save differs:\n" + saved);
  } catch (const std::exception& e) {
    fuzz::finding(std::string("the saved graph does not load: ") + e.what() + "\n" + saved);
  }
  return 0;
}
