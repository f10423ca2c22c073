#include "tests/support/registry_hash_check.h"

#include <gtest/gtest.h>

#include "graph/errors.h"
#include "graph/graph.h"
#include "graph/node_keys.h"
#include "graph/paths.h"

namespace tfd::test {

using namespace tfd::graph;

namespace {

bool valid(const ParamDecl& d, const ParamValue& v) {
  try {
    checkParamValue(d, v);
    return true;
  } catch (const GraphError&) {
    return false;
  }
}

std::vector<double> scalarCandidates(const ParamDecl& d, double v) {
  const double delta = 0.25 * std::abs(v) + 0.125;
  std::vector<double> c{v + delta, v - delta};
  if (d.max) c.push_back(0.5 * (v + *d.max)), c.push_back(*d.max);
  if (d.min) c.push_back(0.5 * (v + *d.min)), c.push_back(*d.min);
  return c;
}

}  // namespace

std::optional<ParamValue> perturbedValue(const ParamDecl& d, const ParamValue& current) {
  auto first = [&](const std::vector<ParamValue>& candidates) -> std::optional<ParamValue> {
    for (const ParamValue& c : candidates)
      if (c != current && valid(d, c)) return checkParamValue(d, c);
    return std::nullopt;
  };
  switch (d.kind) {
    case ParamKind::Bool:
      return ParamValue(!std::get<bool>(current));
    case ParamKind::Int: {
      const auto v = std::get<std::int64_t>(current);
      std::vector<ParamValue> c{v + 1, v - 1};
      if (d.min) c.push_back(static_cast<std::int64_t>(*d.min));
      if (d.max) c.push_back(static_cast<std::int64_t>(*d.max));
      return first(c);
    }
    case ParamKind::Double: {
      std::vector<ParamValue> c;
      for (double x : scalarCandidates(d, std::get<double>(current))) c.push_back(x);
      return first(c);
    }
    case ParamKind::String: {
      const auto& s = std::get<std::string>(current);
      std::vector<ParamValue> c;
      for (const std::string& choice : d.choices) c.push_back(choice);
      if (d.choices.empty()) c = {s + "_changed", std::string("changed")};
      return first(c);
    }
    case ParamKind::Vec3: {
      const auto v = std::get<Vec3Param>(current);
      std::vector<ParamValue> c;
      for (int axis = 0; axis < 3; ++axis)
        for (double x : scalarCandidates(d, v[axis])) {
          Vec3Param p = v;
          p[axis] = x;
          c.push_back(p);
        }
      return first(c);
    }
    case ParamKind::Vec3List: {
      auto list = std::get<std::vector<Vec3Param>>(current);
      std::vector<ParamValue> c;
      if (!list.empty())
        for (double x : scalarCandidates(d, list[0][0])) {
          auto changed = list;
          changed[0][0] = x;
          c.push_back(changed);
        }
      const double fill = d.min ? *d.min : (d.max ? std::min(0.0, *d.max) : 0.0);
      auto longer = list;
      longer.push_back({fill, fill, fill});
      c.push_back(longer);
      return first(c);
    }
    case ParamKind::DoubleList: {
      auto list = std::get<std::vector<double>>(current);
      std::vector<ParamValue> c;
      if (!list.empty())
        for (double x : scalarCandidates(d, list[0])) {
          auto changed = list;
          changed[0] = x;
          c.push_back(changed);
        }
      const double fill = d.min ? *d.min : (d.max ? std::min(0.0, *d.max) : 0.0);
      auto longer = list;
      longer.push_back(fill);
      c.push_back(longer);
      return first(c);
    }
    case ParamKind::StringList: {
      const auto list = std::get<std::vector<std::string>>(current);
      std::vector<ParamValue> c;
      // Each single choice, then the list with its first element dropped.
      for (const std::string& choice : d.choices) c.push_back(std::vector<std::string>{choice});
      if (d.choices.empty()) c.push_back(std::vector<std::string>{"changed"});
      if (!list.empty()) c.push_back(std::vector<std::string>(list.begin() + 1, list.end()));
      return first(c);
    }
  }
  return std::nullopt;
}

void expectEveryParameterChangesHash(const NodeRegistry& registry) {
  for (const NodeType* type : registry.types()) {
    Graph graph(registry);
    const std::string name = graph.addNode(type->name()).name();
    const KeyOptions options{makePathContext(graph), true};
    const Hash base = nodeKey(graph, name, options);
    for (const ParamDecl& p : type->decl().params()) {
      SCOPED_TRACE("node type " + type->name() + ", parameter " + p.name);
      const ParamValue original = graph.param(name, p.name);
      std::optional<ParamValue> changed = perturbedValue(p, original);
      if (!changed) {
        EXPECT_LE(p.choices.size(), 1u) << "no other valid value found to perturb with";
        continue;
      }
      graph.setParam(name, p.name, *changed);
      const Hash perturbed = nodeKey(graph, name, options);
      EXPECT_NE(perturbed, base) << "changing " << p.name << " from " << formatParamValue(original)
                                 << " to " << formatParamValue(*changed)
                                 << " left the key unchanged";
      for (const PortDecl& out : type->decl().outputs())
        EXPECT_NE(outputHash(perturbed, out.name), outputHash(base, out.name))
            << "output " << out.name;
      graph.setParam(name, p.name, original);
      EXPECT_EQ(nodeKey(graph, name, options), base) << "restoring the value changed the key";
    }
  }
}

}  // namespace tfd::test
