#pragma once
// Errors thrown by tfd's core and io layers. Messages name the file, parameter or element at
// fault; the graph layer prefixes the node.
#include <stdexcept>
#include <string>

namespace tfd::core {

/// A failure the user can act on (bad input, unsolvable problem); `what()` says what and where.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown from inside a long computation when its Progress was cancelled.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace tfd::core
