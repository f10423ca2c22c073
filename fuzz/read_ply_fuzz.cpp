// libFuzzer target: the PLY surface reader (io/mesh/surface_readers.h) on any bytes.
#include "fuzz/fuzz_support.h"
#include "io/mesh/surface_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  const auto file = fuzz::inputFile(data, size, "input.ply");
  fuzz::expectReadOrError(file, [&] { fuzz::checkSurface(io::readPly(file)); });
  return 0;
}
