// RemoveCurves through the real nodes (TetGen ball, FieldExpression, ExtractDegenerateCurves,
// exporters): examples/remove_loop.tfd.json removes its mixed loop and keeps the straight
// curve, the VTU marks the region, the curves chain; a refused pick fails the node with the
// reason and nothing downstream cooks or writes.
#include <gtest/gtest.h>

#include <algorithm>
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
      fs::path(TFD_SOURCE_DIR) / "examples" / "remove_loop.tfd.json", test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(12000));
  return g;
}

/// The six components of T = 3 e eᵀ − I + f (u uᵀ − w wᵀ) + g (u wᵀ + w uᵀ) with u = x̂,
/// e = (0, sin 0.3, cos 0.3), w = e × u (as in examples/remove_loop.tfd.json): degenerate
/// (linear) exactly where f = g = 0.
void setTiltedField(graph::Graph& g, const std::string& f, const std::string& gg) {
  const std::string F = "(" + f + ")", G = "(" + gg + ")";
  g.setParam("field", "xx", "-1 + " + F);
  g.setParam("field", "yy", "-0.738003 - 0.912668*" + F);
  g.setParam("field", "zz", "1.738003 - 0.087332*" + F);
  g.setParam("field", "xy", "0.955336*" + G);
  g.setParam("field", "yz", "0.846964 + 0.282321*" + F);
  g.setParam("field", "xz", "-0.295520*" + G);
}

TEST(RemoveCurvesNode, TheExampleRemovesItsLoopAndMarksTheRegion) {
  test::TempDir dir("remove-curves");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(example(), options);
  ASSERT_TRUE(r.ok()) << test::reportText(*r.report("remove"));
  const auto before = r.output<core::DegenerateCurves>("topology", "curves");
  const auto after = r.output<core::DegenerateCurves>("remove", "curves");
  ASSERT_EQ(before->size(), 2u) << before->summary();
  ASSERT_EQ(after->size(), 1u) << after->summary();
  EXPECT_FALSE(after->curve(0).closed) << "the straight curve stays";
  const std::string info = test::reportText(*r.report("remove"));
  EXPECT_NE(info.find("one-loop removal of the linear loop"), std::string::npos) << info;
  EXPECT_NE(info.find("2 curves -> 1"), std::string::npos) << info;
  EXPECT_NE(info.find("region: "), std::string::npos) << info;
  EXPECT_NE(info.find("tries: 1"), std::string::npos) << info;
  const auto region = r.output<core::TetRegion>("remove", "region");
  ASSERT_FALSE(region->tets.empty());
  EXPECT_TRUE(std::is_sorted(region->tets.begin(), region->tets.end()));

  const test::VtkXmlFile vtu = test::readVtkXmlFile(dir.path() / "remove_loop.vtu");
  const auto& cells = vtu.root.child("UnstructuredGrid").child("Piece").child("CellData");
  const std::vector<double> flags = vtu.values(vtu.array(cells, "region"));
  ASSERT_EQ(flags.size(), region->mesh->tetCount());
  std::size_t marked = 0;
  for (std::size_t t = 0; t < flags.size(); ++t) {
    marked += flags[t] == 1;
    EXPECT_EQ(flags[t] == 1, std::binary_search(region->tets.begin(), region->tets.end(), int(t)));
  }
  EXPECT_EQ(marked, region->tets.size());
  EXPECT_TRUE(fs::exists(dir.path() / "curves_before.vtp"));
  EXPECT_TRUE(fs::exists(dir.path() / "curves_after.vtp"));
}

TEST(RemoveCurvesNode, ARefusedPickFailsTheNodeAndNothingDownstreamIsWritten) {
  test::TempDir dir("remove-curves-refused");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Graph g = example();
  g.setParam("remove", "picks", std::vector<graph::Vec3Param>{{0.75, 0.0, 0.1}});
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(g, options);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.report("remove")->state, graph::NodeState::Failed);
  const std::string error = test::reportText(*r.report("remove"));
  EXPECT_NE(error.find("cannot be removed alone"), std::string::npos) << error;
  EXPECT_EQ(r.report("vtu")->state, graph::NodeState::UpstreamFailed);
  EXPECT_EQ(r.report("curves_after")->state, graph::NodeState::UpstreamFailed);
  EXPECT_FALSE(fs::exists(dir.path() / "remove_loop.vtu"));
  EXPECT_FALSE(fs::exists(dir.path() / "curves_after.vtp"));
  EXPECT_TRUE(fs::exists(dir.path() / "curves_before.vtp"));
}

TEST(RemoveCurvesNode, TwoCurveAndOneCurveRemovalOnATetGenBall) {
  struct Case {
    const char* name;
    const char* f;  // f of the tilted field, g = y
    std::vector<graph::Vec3Param> picks;
    std::size_t before, after;
  };
  const Case cases[] = {{"two-curve", "x^2 - 0.09", {{-0.3, 0, 0}, {0.3, 0, 0}}, 2, 0},
                        {"one-curve", "x^2 + z - 0.3", {{0, 0, 0.3}}, 1, 0}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    graph::Graph g = example();
    setTiltedField(g, c.f, "y");
    g.setParam("remove", "picks", c.picks);
    test::TempDir dir("remove-curves-cases");
    graph::CookOptions options;
    options.outDir = dir.path();
    graph::Evaluator ev;
    const graph::CookResult r = ev.cook(g, options);
    ASSERT_EQ(r.output<core::DegenerateCurves>("topology", "curves")->size(), c.before);
    ASSERT_TRUE(r.ok()) << test::reportText(*r.report("remove"));
    EXPECT_EQ(r.output<core::DegenerateCurves>("remove", "curves")->size(), c.after);
    EXPECT_NE(test::reportText(*r.report("remove")).find(std::string(c.name) + " removal"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace tfd::nodes
