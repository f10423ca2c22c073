// FieldExpression: a tensor field from six component expressions in x, y, z (muParser).
#include "core/design/field_expression.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "A tensor field from expressions of x, y, z per component (muParser syntax: + - * / ^, "
       "sin, cos, exp, sqrt, pi, ...). The traceless part is kept.")
      .category("Field");
  d.input<core::TetMesh>("mesh").doc("The volume the field lives on.");
  d.output<core::TensorField>("field").doc(
      "The traceless part of the expressions at every vertex.");
  const char* defaults[6] = {"x", "-x", "0", "y", "0", "0"};
  for (int i = 0; i < 6; ++i) {
    const std::string name = core::tensorComponentNames()[i];
    d.param<std::string>(name)
        .byDefault(defaults[i])
        .check([i](const std::string& text) {
          core::TensorExpressions one;  // the other components stay "0"
          one.components[i] = text;
          core::checkExpressions(one);
        })
        .doc("Expression for T." + name + ".");
  }
}

void cook(graph::CookContext& c) {
  core::TensorExpressions e;
  for (int i = 0; i < 6; ++i)
    e.components[i] = c.param<std::string>(core::tensorComponentNames()[i]);
  c.setOutput("field", std::make_shared<const core::TensorField>(core::evaluateFieldExpression(
                           c.input<core::TetMesh>("mesh"), e, progressOf(c))));
}

}  // namespace

void registerFieldExpression(graph::NodeRegistry& r) { r.add("FieldExpression", 1, declare, cook); }

}  // namespace tfd::nodes
