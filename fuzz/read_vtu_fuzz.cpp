// libFuzzer target: the VTK XML .vtu reader (io/vtk/vtu_reader.h) on any bytes.
#include "fuzz/fuzz_support.h"
#include "io/vtk/vtu_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  fuzz::useSmallMemoryBudget();
  const auto file = fuzz::inputFile(data, size, "input.vtu");
  fuzz::expectReadOrError(file, [&] { fuzz::checkTetMesh(*io::readVtu(file)); });
  return 0;
}
