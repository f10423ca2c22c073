// libFuzzer target: `tfd info` of an OpenVDB file: our handling of what OpenVDB returns or
// throws (io/volume/vdb_reader.h through the info describer). A damaged file must end in
// core::Error naming it, and what it announces is checked against the memory budget.
#include <sstream>

#include "apps/tfd/describe_io_files.h"
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tfd;
  fuzz::useSmallMemoryBudget();
  const auto file = fuzz::inputFile(data, size, "input.vdb");
  std::ostringstream out;
  fuzz::expectReadOrError(file, [&] { cli::describeVdb(file, out); });
  return 0;
}
