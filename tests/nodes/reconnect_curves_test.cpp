// ReconnectCurves through the real nodes (TetGen ball, FieldExpression, ExtractDegenerateCurves,
// exporters): examples/reconnect_loop.tfd.json breaks its mixed loop in two, the info gives
// the ends and the pairing, the VTU marks the region and the curves chain; a pick that names
// the same segment twice fails the node with the reason and nothing downstream is written; a
// wrong number of picks names the parameter.
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
      fs::path(TFD_SOURCE_DIR) / "examples" / "reconnect_loop.tfd.json", test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(15000));
  return g;
}

TEST(ReconnectCurvesNode, TheExampleBreaksItsLoopInTwo) {
  test::TempDir dir("reconnect-curves");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(example(), options);
  ASSERT_TRUE(r.ok()) << test::reportText(*r.report("reconnect"));
  const auto before = r.output<core::DegenerateCurves>("topology", "curves");
  const auto after = r.output<core::DegenerateCurves>("reconnect", "curves");
  ASSERT_EQ(before->size(), 1u) << before->summary();
  ASSERT_EQ(after->size(), 2u) << after->summary();
  EXPECT_TRUE(after->curve(0).closed);
  EXPECT_TRUE(after->curve(1).closed);
  // One loop above the equator z = 0 and one below (by their mean height).
  double mean[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    for (const core::Vec3& p : after->curve(k).points) mean[k] += p.z();
    mean[k] /= double(after->curve(k).points.size());
  }
  EXPECT_GT(std::max(mean[0], mean[1]), 0.2);
  EXPECT_LT(std::min(mean[0], mean[1]), -0.2);
  const std::string info = test::reportText(*r.report("reconnect"));
  for (const char* line : {"reconnection of the linear loop",
                           "end A (segment 1): ", "pairing (Lemma 6.1, Theorem 6.2): A joins ",
                           "sheet (graph shortest", "new curves: ", "tries: 1", "1 curves -> 2"})
    EXPECT_NE(info.find(line), std::string::npos) << line << "\n" << info;
  const auto region = r.output<core::TetRegion>("reconnect", "region");
  ASSERT_FALSE(region->tets.empty());
  const test::VtkXmlFile vtu = test::readVtkXmlFile(dir.path() / "reconnect_loop.vtu");
  const auto& cells = vtu.root.child("UnstructuredGrid").child("Piece").child("CellData");
  const std::vector<double> flags = vtu.values(vtu.array(cells, "region"));
  ASSERT_EQ(flags.size(), region->mesh->tetCount());
  std::size_t marked = 0;
  for (double f : flags) marked += f == 1;
  EXPECT_EQ(marked, region->tets.size());
  EXPECT_TRUE(fs::exists(dir.path() / "curves_after.vtp"));
}

TEST(ReconnectCurvesNode, FailuresNameTheReasonOrTheParameter) {
  struct Case {
    std::vector<graph::Vec3Param> picks;
    const char* message;
  };
  const Case cases[] = {{{{0.6, 0, 0}, {0.6, 0, 0.1}}, "same segment"}, {{{0.6, 0, 0}}, "picks"}};
  for (const Case& c : cases) {
    test::TempDir dir("reconnect-curves-failed");
    graph::CookOptions options;
    options.outDir = dir.path();
    graph::Graph g = example();
    g.setParam("reconnect", "picks", c.picks);
    graph::Evaluator ev;
    const graph::CookResult r = ev.cook(g, options);
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.report("reconnect")->state, graph::NodeState::Failed);
    const std::string error = test::reportText(*r.report("reconnect"));
    EXPECT_NE(error.find(c.message), std::string::npos) << error;
    EXPECT_EQ(r.report("vtu")->state, graph::NodeState::UpstreamFailed);
    EXPECT_FALSE(fs::exists(dir.path() / "reconnect_loop.vtu"));
    EXPECT_FALSE(fs::exists(dir.path() / "curves_after.vtp"));
  }
}

}  // namespace
}  // namespace tfd::nodes
