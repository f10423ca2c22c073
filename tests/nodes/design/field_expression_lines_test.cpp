// Analytic fields typed as FieldExpression graphs (the way a user writes them) have known
// straight degenerate lines (algorithms note §11): F1 (the paper's default L element, Eq. 2-3)
// and F3 (its planar twin), wedge and trisector. Through the real nodes on a TetGen box, and
// through the same expressions on a structured box whose vertices and edges lie on the line:
// one open curve each, within one mean edge length of the line, with the right type and pattern.
#include <gtest/gtest.h>

#include "core/design/field_expression.h"
#include "core/structured_mesh.h"
#include "core/topology/extract_degenerate_curves.h"
#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

struct LineCase {
  const char* name;
  std::array<const char*, 6> expressions;  // xx yy zz xy yz xz
  core::DegenerateType type;
  core::DegeneratePattern pattern;
};

// Each field's degenerate set is exactly the z axis (x = y = 0).
const LineCase kCases[] = {
    {"F1 L-wedge",
     {"x-1", "-x-1", "2", "y", "0", "0"},
     core::DegenerateType::Linear,
     core::DegeneratePattern::Wedge},
    {"F1 L-trisector",
     {"x-1", "-x-1", "2", "-y", "0", "0"},
     core::DegenerateType::Linear,
     core::DegeneratePattern::Trisector},
    {"F3 P-wedge",
     {"1+x", "1-x", "-2", "y", "0", "0"},
     core::DegenerateType::Planar,
     core::DegeneratePattern::Wedge},
    {"F3 P-trisector",
     {"1+x", "1-x", "-2", "-y", "0", "0"},
     core::DegenerateType::Planar,
     core::DegeneratePattern::Trisector},
};

void expectTheZAxis(const core::DegenerateCurves& curves, const LineCase& c, double edge) {
  ASSERT_EQ(curves.size(), 1u) << curves.summary();
  const core::DegenerateCurve& curve = curves.curve(0);
  EXPECT_FALSE(curve.closed);
  EXPECT_EQ(curve.type, c.type);
  int matching = 0;
  double zMin = 1, zMax = -1;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const core::Vec3& p = curve.points[i];
    EXPECT_LT(std::hypot(p.x(), p.y()), edge) << "point " << i;
    matching += curve.patterns[i] == c.pattern;
    zMin = std::min(zMin, p.z()), zMax = std::max(zMax, p.z());
  }
  EXPECT_GT(matching, int(curve.points.size()) * 9 / 10);
  EXPECT_LT(zMin, -1 + edge) << "the curve ends on the boundary";
  EXPECT_GT(zMax, 1 - edge) << "the curve ends on the boundary";
}

std::string graphText(const LineCase& c) {
  std::string params;
  const auto& names = core::tensorComponentNames();
  for (int k = 0; k < 6; ++k)
    params += std::string(k ? ", " : "") + "\"" + names[k] + "\": \"" + c.expressions[k] + "\"";
  return R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "box": {"type": "TetMesh", "typeVersion": 1,
            "params": {"primitive": "box", "target_tets": 12000}},
    "expr": {"type": "FieldExpression", "typeVersion": 1, "params": {)" +
         params + R"(}},
    "topology": {"type": "ExtractDegenerateCurves", "typeVersion": 1}},
    "links": [{"from": "box.mesh", "to": "expr.mesh"},
              {"from": "expr.field", "to": "topology.field"}]})";
}

TEST(AnalyticLines, FieldExpressionGraphsOnATetGenBox) {
  graph::NodeRegistry registry;
  registerAll(registry);
  graph::Evaluator evaluator;
  for (const LineCase& c : kCases) {
    SCOPED_TRACE(c.name);
    const graph::CookResult result =
        evaluator.cook(graph::parseGraph(graphText(c), registry, c.name));
    ASSERT_TRUE(result.ok());
    const auto mesh = result.output<core::TetMesh>("box", "mesh");
    expectTheZAxis(*result.output<core::DegenerateCurves>("topology", "curves"), c,
                   mesh->meanEdgeLength());
  }
}

TEST(AnalyticLines, FieldExpressionsOnAStructuredBoxWhereTheLineRunsAlongEdges) {
  const auto mesh = core::makeBoxMesh(8, 8, 8, core::Vec3(-1, -1, -1), core::Vec3(1, 1, 1));
  for (const LineCase& c : kCases) {
    SCOPED_TRACE(c.name);
    core::TensorExpressions e;
    for (int k = 0; k < 6; ++k) e.components[k] = c.expressions[k];
    expectTheZAxis(core::extractDegenerateCurves(core::evaluateFieldExpression(mesh, e)), c,
                   mesh->meanEdgeLength());
  }
}

}  // namespace
}  // namespace tfd::nodes
