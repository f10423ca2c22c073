// libFuzzer target: the Gmsh .msh reader (format 2.x and 4.x, io/mesh/gmsh.h) on any bytes.
#include "fuzz/fuzz_support.h"
#include "io/mesh/gmsh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  const auto file = fuzz::inputFile(data, size, "input.msh");
  fuzz::expectReadOrError(file, [&] { fuzz::checkTetMesh(*io::readGmsh(file)); });
  return 0;
}
