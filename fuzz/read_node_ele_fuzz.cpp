// libFuzzer target: the TetGen .node/.ele reader (io/tetgen/node_ele.h). The input is both
// files: the .node text, then a line "#ele" and the .ele text (without it, an empty .ele).
#include <string_view>

#include "fuzz/fuzz_support.h"
#include "io/tetgen/node_ele.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::size_t split = all.find("\n#ele\n");
  const std::string_view node = all.substr(0, split);
  const std::string_view ele =
      split == std::string_view::npos ? std::string_view() : all.substr(split + 6);
  const auto bytes = [](std::string_view s) {
    return reinterpret_cast<const std::uint8_t*>(s.data());
  };
  fuzz::inputFile(bytes(ele), ele.size(), "input.ele");
  const auto file = fuzz::inputFile(bytes(node), node.size(), "input.node");
  // Messages name input.node or input.ele: both contain "input.".
  fuzz::expectReadOrError("input.", [&] { fuzz::checkTetMesh(*io::readTetgen(file)); });
  return 0;
}
