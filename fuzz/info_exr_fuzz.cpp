// libFuzzer target: `tfd info` of an OpenEXR slice: our handling of what OpenEXR returns or
// throws (io/volume/exr_reader.h through the info describer).
#include <sstream>

#include "apps/tfd/describe_io_files.h"
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  fuzz::useSmallMemoryBudget();
  const auto file = fuzz::inputFile(data, size, "input.exr");
  std::ostringstream out;
  fuzz::expectReadOrError(file, [&] { cli::describeExr(file, out); });
  return 0;
}
