#include "graph/cook_context.h"

#include <algorithm>

#include "graph/paths.h"

namespace tfd::graph {

namespace {
const std::atomic<bool> kNeverCancelled{false};
}

CookContext::CookContext(std::string nodeName, const NodeDecl& decl, std::vector<ParamValue> params,
                         std::vector<std::vector<Value>> inputs,
                         const std::atomic<bool>* cancelFlag, ProgressCallback progress)
    : nodeName_(std::move(nodeName)),
      decl_(decl),
      params_(std::move(params)),
      inputs_(std::move(inputs)),
      outputs_(decl.outputs().size()),
      cancel_(cancelFlag ? cancelFlag : &kNeverCancelled),
      progress_(std::move(progress)) {
  inputs_.resize(decl.inputs().size());
}

const ParamDecl& CookContext::paramDecl(std::string_view name) const {
  const ParamDecl* d = decl_.findParam(name);
  if (!d)
    throw NodeError("node type " + decl_.typeName() + " has no parameter '" + std::string(name) +
                    "'");
  return *d;
}

int CookContext::paramIndexOf(std::string_view name) const { return decl_.paramIndex(name); }

std::filesystem::path CookContext::path(std::string_view name) const {
  const ParamDecl& d = paramDecl(name);
  if (d.kind != ParamKind::String) throw NodeError("parameter '" + d.name + "' is not a path");
  const std::string& value = std::get<std::string>(params_[paramIndexOf(name)]);
  if (const std::string problem = outputExtensionProblem(d, value); !problem.empty())
    throw paramError(name, problem);
  return std::filesystem::path(value);
}

NodeError CookContext::paramError(std::string_view name, std::string_view message) const {
  return NodeError("parameter '" + std::string(name) + "': " + std::string(message));
}

const std::vector<Value>& CookContext::inputValues(std::string_view port) const {
  int i = decl_.inputIndex(port);
  if (i < 0)
    throw NodeError("node type " + decl_.typeName() + " has no input '" + std::string(port) + "'");
  return inputs_[i];
}

void CookContext::setOutputValue(std::string_view port, Value value) {
  int i = decl_.outputIndex(port);
  if (i < 0)
    throw NodeError("node type " + decl_.typeName() + " has no output '" + std::string(port) + "'");
  const PortDecl& p = decl_.outputs()[i];
  if (!value) throw NodeError("output '" + p.name + "' set to nothing (null)");
  if (value.type != p.type)
    throw NodeError("output '" + p.name + "' is " + std::string(p.type->name) + ", set to " +
                    std::string(value.type ? value.type->name : "?"));
  outputs_[i] = std::move(value);
}

void CookContext::wroteFile(std::filesystem::path path) {
  if (!decl_.hasSideEffects())
    throw NodeError("node type " + decl_.typeName() +
                    " reported a written file but is not declared sideEffect()");
  if (path.empty()) throw NodeError("reported writing a file with an empty path");
  if (std::find(writtenFiles_.begin(), writtenFiles_.end(), path) == writtenFiles_.end())
    writtenFiles_.push_back(std::move(path));
}

void CookContext::progress(double fraction, std::string_view stage) const {
  if (progress_) progress_(std::clamp(fraction, 0.0, 1.0), stage);
}

CookContext::ProgressCallback CookContext::progressCallback() const {
  return [this](double fraction, std::string_view stage) { progress(fraction, stage); };
}

}  // namespace tfd::graph
