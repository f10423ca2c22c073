// DeformCurve through the real nodes (TetGen ball, FieldExpression, ExtractDegenerateCurves,
// exporters): examples/deform_curve.tfd.json bends its straight curve onto the target, the
// VTU marks the region and the curves chain; an extreme target fails the node naming the check,
// and a one-point target names the parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

graph::Graph example() {
  graph::Graph g = graph::loadGraphFile(
      fs::path(TFD_SOURCE_DIR) / "examples" / "deform_curve.tfd.json", test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(15000));
  return g;
}

TEST(DeformCurveNode, TheExampleBendsItsCurveOntoTheTarget) {
  test::TempDir dir("deform-curve");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(example(), options);
  ASSERT_TRUE(r.ok()) << test::reportText(*r.report("deform"));
  const auto before = r.output<core::DegenerateCurves>("topology", "curves");
  const auto after = r.output<core::DegenerateCurves>("deform", "curves");
  ASSERT_EQ(before->size(), 1u) << before->summary();
  ASSERT_EQ(after->size(), 1u) << after->summary();
  double farthest = 0;  // from the z axis: the bump's top is at x = 0.3
  for (const core::Vec3& p : after->curve(0).points)
    farthest = std::max(farthest, std::hypot(p.x(), p.y()));
  const auto region = r.output<core::TetRegion>("deform", "region");
  const double h = region->mesh->meanEdgeLength();
  EXPECT_NEAR(farthest, 0.3, h);
  const std::string info = test::reportText(*r.report("deform"));
  for (const char* line : {"deformation of the linear curve", "region: ", "fold-overs: ",
                           "Hausdorff distance to the target: ", "tries: 1", "1 curves -> 1"})
    EXPECT_NE(info.find(line), std::string::npos) << line << "\n" << info;
  ASSERT_FALSE(region->tets.empty());
  const test::VtkXmlFile vtu = test::readVtkXmlFile(dir.path() / "deform_curve.vtu");
  const auto& cells = vtu.root.child("UnstructuredGrid").child("Piece").child("CellData");
  const std::vector<double> flags = vtu.values(vtu.array(cells, "region"));
  ASSERT_EQ(flags.size(), region->mesh->tetCount());
  std::size_t marked = 0;
  for (double f : flags) marked += f == 1;
  EXPECT_EQ(marked, region->tets.size());
  EXPECT_TRUE(fs::exists(dir.path() / "curves_after.vtp"));
}

TEST(DeformCurveNode, FailuresNameTheCheckOrTheParameter) {
  struct Case {
    std::vector<graph::Vec3Param> target;
    const char* message;
  };
  const Case cases[] = {
      {{{0, 0, -0.3}, {0.5, 0, 0.5}, {-0.5, 0, -0.5}, {0, 0, 0.3}}, "fold-over on the curve"},
      {{{0.2, 0, 0.1}}, "target"}};
  for (const Case& c : cases) {
    test::TempDir dir("deform-curve-failed");
    graph::CookOptions options;
    options.outDir = dir.path();
    graph::Graph g = example();
    g.setParam("deform", "target", c.target);
    g.setParam("deform", "retries", std::int64_t(0));
    graph::Evaluator ev;
    const graph::CookResult r = ev.cook(g, options);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.report("deform")->state, graph::NodeState::Failed);
    const std::string error = test::reportText(*r.report("deform"));
    EXPECT_NE(error.find(c.message), std::string::npos) << error;
    EXPECT_EQ(r.report("vtu")->state, graph::NodeState::UpstreamFailed);
    EXPECT_FALSE(fs::exists(dir.path() / "deform_curve.vtu"));
  }
}

}  // namespace
}  // namespace tfd::nodes
