#pragma once
// A reusable property test over any node registry: every parameter of every node type must
// feed the node's cache key (CONVENTIONS.md "Evaluation": a test perturbs each parameter of
// each node type and checks the output hash changes). Run it over the real registry
// (nodes::registerAll) as well as the test registry.
#include <optional>

#include "graph/node_registry.h"
#include "graph/param.h"

namespace tfd::test {

/// For each node type and each parameter: builds a graph with one node of that type, sets the
/// parameter to a different valid value (perturbedValue) and EXPECTs the node key and the hash
/// of every output to change, and to return to the original when the value is restored.
/// Parameters with no other valid value (a single choice) are reported with ADD_FAILURE unless
/// that is the only possibility for their declaration.
void expectEveryParameterChangesHash(const graph::NodeRegistry& registry);

/// A valid value (passes checkParamValue) different from `current`, or nothing when the
/// declaration allows no other value.
std::optional<graph::ParamValue> perturbedValue(const graph::ParamDecl& decl,
                                                const graph::ParamValue& current);

}  // namespace tfd::test
