#pragma once
// Exceptions of the graph layer. The graph layer knows nothing of core::Error; node cook
// functions may throw any std::exception and the evaluator turns it into that node's error.
#include <stdexcept>
#include <string>

namespace tfd::graph {

/// A graph edit or graph-level operation was refused (unknown node, bad link, bad parameter
/// value, cycle...). `what()` names the node, port or parameter at fault.
class GraphError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A graph file could not be loaded. Points at the place: the file, a JSON pointer into it
/// (e.g. "/nodes/propagate1/params/radius") and what was expected and found.
/// what() == "<file> at <pointer>: <message>" (or "<file>: <message>" without a pointer).
class LoadError : public GraphError {
 public:
  LoadError(std::string file, std::string pointer, std::string message);
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, pointer_, message_;
};

/// Thrown by a node's cook function for a failure the user can act on; the message becomes the
/// node's error (the CLI prints `tfd: node "name" (Type): <message>`).
class NodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by CookContext::throwIfCancelled(). The evaluator treats any exception thrown while
/// the cancel flag is set as a cancellation, so core::Cancelled works just as well.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace tfd::graph
