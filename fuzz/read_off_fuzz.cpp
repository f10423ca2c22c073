// libFuzzer target: the OFF surface reader (io/mesh/surface_readers.h) on any bytes.
#include "fuzz/fuzz_support.h"
#include "io/mesh/surface_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  const auto file = fuzz::inputFile(data, size, "input.off");
  fuzz::expectReadOrError(file, [&] { fuzz::checkSurface(io::readOff(file)); });
  return 0;
}
