#include "graph/errors.h"

#include "graph/json_text.h"

namespace tfd::graph {

namespace {
std::string composeLoadMessage(const std::string& file, const std::string& pointer,
                               const std::string& message) {
  std::string out = file.empty() ? std::string("<graph>") : file;
  if (!pointer.empty()) out += " at " + pointer;
  return out + ": " + message;
}
}  // namespace

// Names, keys and strings from the file reach messages: control bytes are escaped here, once,
// so a damaged or hostile file never writes raw bytes to a terminal.
LoadError::LoadError(std::string file, std::string pointer, std::string message)
    : GraphError(composeLoadMessage(file, printableText(pointer), printableText(message))),
      file_(std::move(file)),
      pointer_(printableText(pointer)),
      message_(printableText(message)) {}

}  // namespace tfd::graph
