#pragma once
// What a node's cook function sees: its resolved parameters, its input values, a place for its
// outputs, message reporting, progress and the cancellation flag.
//
//   static void cook(graph::CookContext& c) {
//     auto mesh = c.input<core::TetMesh>("mesh");                   // shared_ptr<const TetMesh>
//     auto sets = c.inputs<core::ConstraintSet>("constraints");      // every link, file order
//     double tol = c.param<double>("tolerance");
//     std::filesystem::path out = c.path("path");                    // resolved file parameter
//     core::Progress progress(c.progressCallback(), &c.cancelFlag());
//     c.setOutput("field", std::make_shared<const core::TensorField>(...));
//     c.info("fixed 120 vertices");
//   }
//
// A side-effect node (NodeDecl::sideEffect, the exporters) calls c.wroteFile(path) for every
// file it wrote, after writing it; the evaluator records the files' size and modification time
// and answers "which files did this cook write" (NodeReport::files, CookResult::writtenFiles).
//
// Errors: throw graph::NodeError (or core::Error, or any std::exception); the message becomes
// the node's error. Misuse (unknown port/parameter name, wrong C++ type) throws NodeError too,
// naming the port or parameter. A CookContext is used by one thread at a time, except
// cancelFlag()/cancelled(), which any worker thread may read.
#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/errors.h"
#include "graph/node_decl.h"
#include "graph/node_message.h"
#include "graph/value.h"

namespace tfd::graph {

class CookContext {
 public:
  using ProgressCallback = std::function<void(double fraction, std::string_view stage)>;

  /// Built by the evaluator. `params` are the node's effective values in declaration order
  /// with file paths resolved; `inputs[i]` holds the values linked into input i in file order.
  CookContext(std::string nodeName, const NodeDecl& decl, std::vector<ParamValue> params,
              std::vector<std::vector<Value>> inputs, const std::atomic<bool>* cancelFlag,
              ProgressCallback progress);

  const std::string& nodeName() const { return nodeName_; }
  const NodeDecl& decl() const { return decl_; }

  // ---- parameters
  template <class T>
  T param(std::string_view name) const {
    const ParamDecl& d = paramDecl(name);
    if (d.kind != ParamTraits<T>::kind)
      throw NodeError("parameter '" + d.name + "' is " + std::string(kindName(d.kind)) +
                      ", read as " + std::string(kindName(ParamTraits<T>::kind)));
    try {
      return ParamTraits<T>::fromValue(params_[paramIndexOf(name)]);
    } catch (const GraphError& e) {
      throw NodeError("parameter '" + d.name + "': " + e.what());
    }
  }
  /// An enum parameter as its enum, through the table it was declared with.
  template <class E>
  E param(std::string_view name, const Choices<E>& table) const {
    return table.value(param<std::string>(name));
  }
  /// A string-list parameter of choices as enums, in the order given.
  template <class E>
  std::vector<E> paramList(std::string_view name, const Choices<E>& table) const {
    std::vector<E> out;
    for (const std::string& s : param<std::vector<std::string>>(name))
      out.push_back(table.value(s));
    return out;
  }
  /// A file parameter, resolved (input files against the graph's folder, outputs against the
  /// output directory). Empty when the parameter is empty.
  std::filesystem::path path(std::string_view name) const;
  /// A NodeError "parameter 'name': message" for the node to throw.
  NodeError paramError(std::string_view name, std::string_view message) const;

  // ---- inputs
  bool hasInput(std::string_view port) const { return !inputValues(port).empty(); }
  /// The single value linked into `port`; throws NodeError when nothing is linked.
  template <class T>
  std::shared_ptr<const T> input(std::string_view port) const {
    const auto& values = inputValues(port);
    if (values.empty()) throw NodeError("input '" + std::string(port) + "' is not connected");
    return typed<T>(values.front(), port);
  }
  /// The linked value, or `fallback` when the (optional) input is not connected.
  template <class T>
  std::shared_ptr<const T> inputOr(std::string_view port,
                                   std::shared_ptr<const T> fallback = nullptr) const {
    const auto& values = inputValues(port);
    return values.empty() ? fallback : typed<T>(values.front(), port);
  }
  /// Every value linked into a `multiple` input, in file order (possibly none).
  template <class T>
  std::vector<std::shared_ptr<const T>> inputs(std::string_view port) const {
    std::vector<std::shared_ptr<const T>> out;
    for (const Value& v : inputValues(port)) out.push_back(typed<T>(v, port));
    return out;
  }

  // ---- outputs
  template <class T>
  void setOutput(std::string_view port, std::shared_ptr<const T> value) {
    setOutputValue(port, Value::of<T>(std::move(value)));
  }
  template <class T>
  void setOutput(std::string_view port, std::shared_ptr<T> value) {
    setOutput<T>(port, std::shared_ptr<const T>(std::move(value)));
  }
  void setOutputValue(std::string_view port, Value value);

  // ---- files (side-effect nodes only)
  /// Records a file this cook wrote (call it after the file is complete). Throws NodeError for
  /// a node type not declared sideEffect(). Reporting a file twice keeps the first.
  void wroteFile(std::filesystem::path path);
  const std::vector<std::filesystem::path>& writtenFiles() const { return writtenFiles_; }

  // ---- messages, progress, cancellation
  void info(std::string text) { messages_.push_back({Severity::Info, std::move(text)}); }
  void warning(std::string text) { messages_.push_back({Severity::Warning, std::move(text)}); }
  /// Fraction of this node's work done, in [0, 1], with an optional stage name. Call from the
  /// thread that runs cook (not from worker threads).
  void progress(double fraction, std::string_view stage = {}) const;
  /// A callback to build a core::Progress with: core::Progress(c.progressCallback(),
  /// &c.cancelFlag()).
  ProgressCallback progressCallback() const;
  /// Set when the cook is being cancelled; long loops check it (any thread may read it).
  const std::atomic<bool>& cancelFlag() const { return *cancel_; }
  bool cancelled() const { return cancel_->load(std::memory_order_relaxed); }
  void throwIfCancelled() const {
    if (cancelled()) throw Cancelled();
  }

  // ---- for the evaluator
  std::vector<Value>& outputs() { return outputs_; }
  std::vector<NodeMessage>& messages() { return messages_; }

 private:
  const ParamDecl& paramDecl(std::string_view name) const;
  int paramIndexOf(std::string_view name) const;
  const std::vector<Value>& inputValues(std::string_view port) const;
  template <class T>
  std::shared_ptr<const T> typed(const Value& v, std::string_view port) const {
    auto p = v.as<T>();
    if (!p)
      throw NodeError("input '" + std::string(port) + "' holds " +
                      std::string(v.type ? v.type->name : "nothing") + ", read as " +
                      std::string(valueType<T>()->name));
    return p;
  }

  std::string nodeName_;
  const NodeDecl& decl_;
  std::vector<ParamValue> params_;
  std::vector<std::vector<Value>> inputs_;
  std::vector<Value> outputs_;
  std::vector<NodeMessage> messages_;
  std::vector<std::filesystem::path> writtenFiles_;
  const std::atomic<bool>* cancel_;
  ProgressCallback progress_;
};

}  // namespace tfd::graph
