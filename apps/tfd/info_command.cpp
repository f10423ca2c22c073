// tfd info FILE: a summary of a graph file or of any file kind registered in
// register_describers.cpp.
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
    // A damaged file can make a library allocate without bound: cap the address space.
    const core::AddressSpaceCap cap;
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
