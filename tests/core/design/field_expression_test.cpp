#include "core/design/field_expression.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/structured_mesh.h"

namespace tfd::core {
namespace {

TEST(FieldExpression, EvaluatesTheTracelessPartAtEveryVertex) {
  const auto mesh = makeBoxMesh(4, 4, 4, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  TensorExpressions e;
  e.components = {"x + 3", "-x + 3", "2 + 3", "y", "sin(z)", "x*y*z"};
  const TensorField f = evaluateFieldExpression(mesh, e);
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {
    const Vec3& p = mesh->positions()[v];
    const Tensor expected =
        Tensor{p.x() + 3, -p.x() + 3, 5, p.y(), std::sin(p.z()), p.x() * p.y() * p.z()}.deviator();
    EXPECT_NEAR((f.at(int(v)) - expected).norm(), 0, 1e-14);
  }
}

TEST(FieldExpression, NamesTheBadComponent) {
  TensorExpressions e;
  e.components[3] = "x * * y";
  try {
    checkExpressions(e);
    FAIL() << "expected an error";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("component \"xy\""), std::string::npos) << err.what();
  }
  e.components[3] = "w + 1";  // unknown variable
  EXPECT_THROW(checkExpressions(e), Error);
}

TEST(FieldExpression, RefusesNonFiniteValues) {
  const auto mesh = makeBoxMesh(2, 2, 2, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  TensorExpressions e;
  e.components[0] = "1/x";
  try {
    evaluateFieldExpression(mesh, e);
    FAIL() << "expected an error";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("non-finite tensor at (0, -1, -1)"), std::string::npos)
        << err.what();
  }
}

}  // namespace
}  // namespace tfd::core
