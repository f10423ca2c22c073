// tfd info FILE: a summary of a graph file or of any file kind registered in
// register_describers.cpp.
#include <algorithm>
#include <iostream>
#include <new>

#include "apps/tfd/cli.h"
#include "apps/tfd/file_describers.h"
#include "core/memory_budget.h"

namespace tfd::cli {

namespace {

int runInfo(const std::string& file, const Context& context) {
  FileDescribers describers;
  registerFileDescribers(describers, context.registry);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    printError(file + ": no such file");
    return kUsage;
  }
  const Describer* describe = describers.find(file);
  if (!describe) {
    printError(file + ": no describer for this kind of file (known: " + describers.known() + ")");
    return kUsage;
  }
  try {
    // A damaged file can make a library allocate without bound (a 10 KB .vdb grew OpenVDB to
    // 10 GB): cap the address space at the budget, by default also at 1 GB + 256 bytes per
    // byte of the file, far more than describing any intact file takes.
    std::uint64_t bytes = core::memoryBudget();
    const std::uintmax_t fileBytes = std::filesystem::file_size(file, ec);
    if (!core::memoryBudgetIsExplicit() && !ec && fileBytes < (std::uintmax_t(1) << 40))
      bytes = std::min<std::uint64_t>(bytes, (std::uint64_t(1) << 30) + 256 * fileBytes);
    const core::AddressSpaceCap cap(bytes);
    return (*describe)(file, std::cout);
  } catch (const std::bad_alloc&) {
    printError(file + ": reading it needs more memory than the budget allows (a damaged file?)");
    return kUsage;
  } catch (const std::exception& e) {
    printError(file + ": " + e.what());
    return kUsage;
  }
}

}  // namespace

void addInfoCommand(CLI::App& app, const Context& context, int& exitCode) {
  auto file = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a file (graph, mesh, field export...).");
  cmd->add_option("file", *file, "The file.")->required();
  addMaxMemoryOption(*cmd);
  cmd->callback([file, &context, &exitCode] { exitCode = runInfo(*file, context); });
}

}  // namespace tfd::cli
