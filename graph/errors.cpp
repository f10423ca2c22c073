#include "graph/errors.h"

namespace tfd::graph {

namespace {
std::string composeLoadMessage(const std::string& file, const std::string& pointer,
                               const std::string& message) {
  std::string out = file.empty() ? std::string("<graph>") : file;
  if (!pointer.empty()) out += " at " + pointer;
  return out + ": " + message;
}
}  // namespace

LoadError::LoadError(std::string file, std::string pointer, std::string message)
    : GraphError(composeLoadMessage(file, pointer, message)),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      message_(std::move(message)) {}

}  // namespace tfd::graph
