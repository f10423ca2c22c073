// examples/edit_sequence.tfd.json (after the paper's Figure 9) through the real nodes: a mixed
// loop removed (§6.4), a straight curve bent into the space the loop left (§6.1), and the two
// branches of a hyperbola reconnected (§6.2), each edit cooking the previous one's field and
// curves, with the curves exported after every step.
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

double meanX(const core::DegenerateCurve& c) {
  double x = 0;
  for (const core::Vec3& p : c.points) x += p.x();
  return x / double(c.points.size());
}

/// The curves right of the deformed line (x > 0.2): the hyperbola's two branches.
std::vector<const core::DegenerateCurve*> branches(const core::DegenerateCurves& curves) {
  std::vector<const core::DegenerateCurve*> out;
  for (const core::DegenerateCurve& c : curves.curves())
    if (meanX(c) > 0.2) out.push_back(&c);
  return out;
}

std::string linesIn(const fs::path& vtp) {
  const test::VtkXmlFile file = test::readVtkXmlFile(vtp);
  return file.root.child("PolyData").child("Piece").attribute("NumberOfLines");
}

TEST(EditSequenceExample, RemovesDeformsAndReconnectsInSequence) {
  graph::Graph g = graph::loadGraphFile(
      fs::path(TFD_SOURCE_DIR) / "examples" / "edit_sequence.tfd.json", test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(15000));
  test::TempDir dir("edit-sequence");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(g, options);
  for (const char* node : {"remove", "deform", "reconnect"})
    ASSERT_EQ(r.report(node)->state, graph::NodeState::Cooked) << test::reportText(*r.report(node));
  ASSERT_TRUE(r.ok());

  // Designed: a mixed loop, a straight curve x = -0.15 and the two branches of a hyperbola.
  const auto designed = r.output<core::DegenerateCurves>("topology", "curves");
  ASSERT_EQ(designed->size(), 4u) << designed->summary();
  EXPECT_EQ(std::count_if(designed->curves().begin(), designed->curves().end(),
                          [](const core::DegenerateCurve& c) { return c.closed; }),
            1);

  const auto removed = r.output<core::DegenerateCurves>("remove", "curves");
  ASSERT_EQ(removed->size(), 3u) << removed->summary();
  for (const core::DegenerateCurve& c : removed->curves()) EXPECT_FALSE(c.closed);

  // The straight curve now bulges to x = -0.33 where the loop was.
  const auto deformed = r.output<core::DegenerateCurves>("deform", "curves");
  ASSERT_EQ(deformed->size(), 3u) << deformed->summary();
  const double h = r.output<core::TetRegion>("deform", "region")->mesh->meanEdgeLength();
  double leftmost = 0;
  for (const core::DegenerateCurve& c : deformed->curves())
    if (meanX(c) < 0.2)
      for (const core::Vec3& p : c.points) leftmost = std::min(leftmost, p.x());
  EXPECT_NEAR(leftmost, -0.33, h);

  // Before: each branch runs from the bottom of the ball to its top. After: each new curve
  // has both ends on one side of z = 0 (one above, one below).
  for (const core::DegenerateCurve* c : branches(*deformed))
    EXPECT_LT(c->points.front().z() * c->points.back().z(), 0) << "a branch crosses z = 0";
  const auto reconnected = r.output<core::DegenerateCurves>("reconnect", "curves");
  ASSERT_EQ(reconnected->size(), 3u) << reconnected->summary();
  const auto joined = branches(*reconnected);
  ASSERT_EQ(joined.size(), 2u);
  double side = 1;
  for (const core::DegenerateCurve* c : joined) {
    EXPECT_GT(c->points.front().z() * c->points.back().z(), 0) << "both ends on one side";
    side *= c->points.front().z();
  }
  EXPECT_LT(side, 0) << "one new curve above z = 0, one below";
  const std::string info = test::reportText(*r.report("reconnect"));
  EXPECT_NE(info.find("pairing (Lemma 6.1, Theorem 6.2)"), std::string::npos) << info;

  const char* files[] = {"edit_sequence_0_designed.vtp", "edit_sequence_1_removed.vtp",
                         "edit_sequence_2_deformed.vtp", "edit_sequence_3_reconnected.vtp"};
  const char* counts[] = {"4", "3", "3", "3"};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(linesIn(dir.path() / files[k]), counts[k]) << files[k];
  EXPECT_TRUE(fs::exists(dir.path() / "edit_sequence.vtu"));
}

}  // namespace
}  // namespace tfd::nodes
