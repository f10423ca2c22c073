#pragma once
// The declaration of a node type: named, typed input and output ports and parameters with
// metadata. Filled by a node file's declare function; the one source for validation, the CLI
// reference (`tfd nodes`), an editor's parameter panel and the cache key.
//
//   static void declare(graph::NodeDecl& d) {
//     d.doc("Harmonic propagation of design constraints (paper §5).").category("Design");
//     d.input<core::TetMesh>("mesh").doc("The volume.");
//     // an exporter also says d.sideEffect() and reports its files with c.wroteFile(path)
//     d.input<core::ConstraintSet>("constraints").optional().multiple();
//     d.output<core::TensorField>("field");
//     d.param<double>("tolerance").byDefault(1e-8).min(1e-14).max(1e-2).doc("...");
//     d.param<std::string>("primitive").choices({"sphere", "box"}).doc("...");  // default: first
//     d.param<std::string>("path").byDefault("field.vtu").outputFile("*.vtu");
//     d.param<std::vector<double>>("eigenvalues").size(3).byDefault({1, 0, -1});
//     d.migration(1, [](graph::Json& params) { ... });  // typeVersion 1 -> 2 of the params
//   }
//
// References returned by the builders stay valid for the declaration's lifetime.
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "graph/json_fwd.h"
#include "graph/param.h"
#include "graph/value.h"

namespace tfd::graph {

struct PortDecl {
  std::string name;
  const ValueType* type = nullptr;
  bool optional = false;  ///< inputs: may stay unconnected
  bool multiple = false;  ///< inputs: accepts several links, kept in file order
  std::string doc;
};

class PortBuilder {
 public:
  explicit PortBuilder(PortDecl& port) : port_(port) {}
  /// Inputs only: the node cooks without it (read with CookContext::inputOr / hasInput).
  PortBuilder& optional(bool on = true) {
    port_.optional = on;
    return *this;
  }
  /// Inputs only: accepts any number of links (read with CookContext::inputs), in file order.
  PortBuilder& multiple(bool on = true) {
    port_.multiple = on;
    return *this;
  }
  PortBuilder& doc(std::string text) {
    port_.doc = std::move(text);
    return *this;
  }
  const PortDecl& decl() const { return port_; }

 private:
  PortDecl& port_;
};

template <class T>
class ParamBuilder {
 public:
  explicit ParamBuilder(ParamDecl& param) : p_(param) {}
  ParamBuilder& byDefault(T value) {
    p_.defaultValue = ParamTraits<T>::toValue(std::move(value));
    return *this;
  }
  ParamBuilder& min(double v) {
    p_.min = v;
    return *this;
  }
  ParamBuilder& max(double v) {
    p_.max = v;
    return *this;
  }
  ParamBuilder& range(double lo, double hi) { return min(lo).max(hi); }
  /// String parameters: the allowed values (an enum). Without byDefault the first is default.
  ParamBuilder& choices(std::vector<std::string> values) {
    p_.choices = std::move(values);
    return *this;
  }
  /// An enum parameter (string) or a set of options (string list) from its string table.
  template <class E>
  ParamBuilder& choices(const Choices<E>& table) {
    return choices(table.names());
  }
  /// Double lists: exact number of values (the default becomes that many zeros if not set).
  ParamBuilder& size(std::size_t n) {
    p_.size = n;
    return *this;
  }
  /// Lists: fewest elements.
  ParamBuilder& minSize(std::size_t n) {
    p_.minSize = n;
    return *this;
  }
  ParamBuilder& doc(std::string text) {
    p_.doc = std::move(text);
    return *this;
  }
  ParamBuilder& label(std::string text) {
    p_.label = std::move(text);
    return *this;
  }
  ParamBuilder& hint(UiHint h) {
    p_.hint = h;
    return *this;
  }
  /// String parameters: a file read by the node; relative to the graph file's folder.
  ParamBuilder& inputFile(std::string filter = {}) {
    p_.hint = UiHint::InputFile;
    p_.fileFilter = std::move(filter);
    return *this;
  }
  /// String parameters: a file written by the node; relative to --out (or the graph's folder).
  ParamBuilder& outputFile(std::string filter = {}) {
    p_.hint = UiHint::OutputFile;
    p_.fileFilter = std::move(filter);
    return *this;
  }
  /// A check beyond range and choices: `fn` throws std::exception saying what is wrong.
  ParamBuilder& check(std::function<void(const T&)> fn) {
    p_.check = [fn = std::move(fn)](const ParamValue& v) { fn(ParamTraits<T>::fromValue(v)); };
    return *this;
  }
  const ParamDecl& decl() const { return p_; }

 private:
  ParamDecl& p_;
};

/// Upgrades a node's "params" object from typeVersion N to N+1 (pure JSON -> JSON, in place).
/// Throw std::exception with a message on data it cannot upgrade.
using ParamMigration = std::function<void(Json& params)>;

class NodeDecl {
 public:
  NodeDecl(std::string typeName, int typeVersion)
      : typeName_(std::move(typeName)), typeVersion_(typeVersion) {}

  const std::string& typeName() const { return typeName_; }
  int typeVersion() const { return typeVersion_; }

  NodeDecl& doc(std::string text) {
    doc_ = std::move(text);
    return *this;
  }
  NodeDecl& category(std::string text) {
    category_ = std::move(text);
    return *this;
  }
  /// The node acts outside the graph: it writes files (an exporter) and reports each with
  /// CookContext::wroteFile. Within one Evaluator such a node cooks again, although its cache
  /// key is unchanged, when a file it wrote went missing or changed on disk.
  NodeDecl& sideEffect(bool on = true) {
    sideEffect_ = on;
    return *this;
  }
  const std::string& doc() const { return doc_; }
  const std::string& category() const { return category_; }
  bool hasSideEffects() const { return sideEffect_; }

  template <class T>
  PortBuilder input(std::string name) {
    PortDecl& p = inputs_.emplace_back();
    p.name = std::move(name);
    p.type = valueType<T>();
    return PortBuilder(p);
  }
  template <class T>
  PortBuilder output(std::string name) {
    PortDecl& p = outputs_.emplace_back();
    p.name = std::move(name);
    p.type = valueType<T>();
    return PortBuilder(p);
  }
  template <class T>
  ParamBuilder<T> param(std::string name) {
    ParamDecl& p = params_.emplace_back();
    p.name = std::move(name);
    p.kind = ParamTraits<T>::kind;
    p.defaultValue = ParamTraits<T>::toValue(T{});
    return ParamBuilder<T>(p);
  }
  /// Registers the upgrade of stored params from typeVersion `fromVersion` to fromVersion + 1.
  NodeDecl& migration(int fromVersion, ParamMigration upgrade) {
    migrations_[fromVersion] = std::move(upgrade);
    return *this;
  }

  const std::deque<PortDecl>& inputs() const { return inputs_; }
  const std::deque<PortDecl>& outputs() const { return outputs_; }
  const std::deque<ParamDecl>& params() const { return params_; }
  /// Index into inputs()/outputs()/params(), or -1.
  int inputIndex(std::string_view name) const;
  int outputIndex(std::string_view name) const;
  int paramIndex(std::string_view name) const;
  const PortDecl* findInput(std::string_view name) const;
  const PortDecl* findOutput(std::string_view name) const;
  const ParamDecl* findParam(std::string_view name) const;
  const ParamMigration* migrationFrom(int fromVersion) const;
  /// A sink (exporter) has no outputs; it is cooked when the whole graph is cooked.
  bool isSink() const { return outputs_.empty(); }

  /// Checks names (identifiers, unique), port types, defaults against their own range,
  /// choices and size; fills implicit defaults (first choice, zeros of a fixed size).
  /// Throws std::logic_error naming the type and the offending declaration.
  void finalize();

 private:
  std::string typeName_;
  int typeVersion_;
  std::string doc_, category_;
  bool sideEffect_ = false;
  std::deque<PortDecl> inputs_, outputs_;
  std::deque<ParamDecl> params_;
  std::map<int, ParamMigration> migrations_;
};

}  // namespace tfd::graph
