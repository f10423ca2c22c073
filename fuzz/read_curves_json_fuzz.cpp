// libFuzzer target: the degenerate-curve JSON reader (io/curves/curve_json_reader.h).
#include "fuzz/fuzz_support.h"
#include "io/curves/curve_json_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  const auto file = fuzz::inputFile(data, size, "input.json");
  fuzz::expectReadOrError(file, [&] { (void)io::readCurvesJson(file); });
  return 0;
}
