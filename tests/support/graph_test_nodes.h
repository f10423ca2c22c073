#pragma once
// Dummy value and node types for the graph engine's tests (the graph layer knows no tensors).
//
//   Constant   param value:double            -> out:Number
//   Add        a:Number, b:Number            -> sum:Number      param bias:double
//   Sum        values:Number (optional, multiple) -> out:Number (sum; records the link order)
//   Scale v2   in:Number                     -> out:Number      params factor, fail, warn
//              (typeVersion 1 named the factor "multiplier": a parameter migration)
//   Sink       in:Number (no outputs)        records the value;  param path:output file
//   WriteFile  in:Number (no outputs, side effect) writes the value to `path` and, for
//              copies > 1, to path.1 ... path.<copies-1>; reports each with wroteFile
//   Wait       in:Number (optional)          -> out:Number      params seconds, ignore_cancel
//   Rendezvous                               -> out:Number      waits for a second Rendezvous
//   Blob       param kilobytes:int           -> out:Blob (sized value for the cache budget)
//   Concat     texts:Text (multiple)         -> out:Text        param separator
//   ReadText   param path:input file         -> out:Text (the file's content)
//   AllParams  every parameter kind          -> out:Text (the parameters formatted)
//   Lazy       in:Number                     -> out:Number  (forgets to set its output)
#include <atomic>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "graph/node_registry.h"
#include "graph/value.h"

namespace tfd::test {

struct Number {
  double value = 0;
};
struct Text {
  std::string value;
};
struct Blob {
  std::vector<char> bytes;
};

}  // namespace tfd::test

TFD_GRAPH_VALUE_TYPE(tfd::test::Number, "Number");
TFD_GRAPH_VALUE_TYPE(tfd::test::Text, "Text");
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::test::Blob, "Blob",
                           [](const tfd::test::Blob& b) { return b.bytes.size(); });

namespace tfd::test {

/// Which nodes cooked, thread-safe. Reset it at the start of each test.
class CookLog {
 public:
  void record(const std::string& node);
  int count(const std::string& node) const;
  int total() const;
  std::vector<std::string> nodes() const;  ///< in cook order
  void clear();
  /// Values received by Sink nodes, by node name.
  void sink(const std::string& node, double value);
  std::map<std::string, double> sinks() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> order_;
  std::map<std::string, double> sinks_;
};
CookLog& cookLog();

/// Rendezvous nodes: how many arrived, and the most that were inside cook at once.
struct RendezvousState {
  std::atomic<int> arrived{0};
  std::atomic<int> inside{0};
  std::atomic<int> peak{0};
  void reset() { arrived = 0, inside = 0, peak = 0; }
};
RendezvousState& rendezvous();

void registerTestNodes(graph::NodeRegistry& registry);

}  // namespace tfd::test
