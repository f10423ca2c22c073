// A designed degenerate point must read as designed: with PointConstraint's default support
// (auto, kAutoPointSupportEdges mean edge lengths) the default example's four degenerate points
// each lie on a curve of their type at least a few edges long, and ExtractDegenerateCurves
// says so; with the old support (the holding tet only) the same points give specks, and the
// node warns about them.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/design/design_element.h"
#include "core/topology/design_point_curves.h"
#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

const char* kPoints[] = {"linear_wedge", "planar_trisector", "linear_trisector", "planar_wedge"};

struct Cooked {
  graph::CookResult result;
  std::vector<core::DesignPointCurve> points;
  double meanEdge = 0;
};

Cooked cookDefault(const char* support) {
  graph::Graph g = graph::loadGraphFile(fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json",
                                        test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(20000));
  for (const char* p : kPoints) g.setParam(p, "support", std::string(support));
  graph::CookOptions options;
  options.targets = {"topology"};
  graph::Evaluator ev;
  Cooked c{ev.cook(g, options), {}, 0};
  EXPECT_TRUE(c.result.ok());
  const auto curves = c.result.output<core::DegenerateCurves>("topology", "curves");
  const auto design = c.result.output<core::ConstraintSet>("design", "constraints");
  const auto mesh = c.result.output<core::TetMesh>("ball", "mesh");
  if (!curves || !design || !mesh) return c;
  c.meanEdge = mesh->meanEdgeLength();
  c.points = core::curvesThroughDesignPoints(*curves, *design, c.meanEdge);
  return c;
}

int pointWarnings(const graph::CookResult& r) {
  int n = 0;
  for (const graph::NodeMessage& m : r.report("topology")->messages)
    n += m.severity == graph::Severity::Warning && m.text.find("degenerate point") == 0;
  return n;
}

TEST(DesignPointReport, DefaultSupportGivesEveryDesignedPointAVisibleCurveOfItsType) {
  const Cooked c = cookDefault("auto");
  ASSERT_EQ(c.points.size(), 4u);
  for (const core::DesignPointCurve& p : c.points) {
    SCOPED_TRACE("element " + std::to_string(p.element));
    ASSERT_TRUE(p.pick.has_value());
    EXPECT_TRUE(p.typeMatches);
    EXPECT_FALSE(p.speck);
    // The linearisation's degenerate line is kept across the whole support ball.
    EXPECT_GE(p.length, 1.6 * core::kAutoPointSupportEdges * c.meanEdge);
  }
  EXPECT_EQ(pointWarnings(c.result), 0);
  int lines = 0;
  for (const graph::NodeMessage& m : c.result.report("topology")->messages)
    lines += m.severity == graph::Severity::Info && m.text.find("degenerate point") == 0;
  EXPECT_EQ(lines, 4);
}

TEST(DesignPointReport, TetSupportGivesSpecksAndTheNodeWarns) {
  const Cooked c = cookDefault("tet");
  ASSERT_EQ(c.points.size(), 4u);
  int bad = 0;
  for (const core::DesignPointCurve& p : c.points) bad += !p.pick || p.speck || !p.typeMatches;
  EXPECT_GE(bad, 1);
  EXPECT_EQ(pointWarnings(c.result), bad);
}

}  // namespace
}  // namespace tfd::nodes
