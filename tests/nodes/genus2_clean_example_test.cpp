// examples/genus2_clean.tfd.json through the real nodes, at its own size (250k tets: the curves
// it names exist at that mesh only, so this is the one slow example test, about 10 s): the
// unwanted linear curve beside the designed trisector line is removed, every other curve is
// kept exactly, and both designed curves remain.
#include <gtest/gtest.h>

#include <filesystem>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

bool passesNear(const core::DegenerateCurve& c, const core::Vec3& p, double distance) {
  for (const core::Vec3& q : c.points)
    if ((q - p).norm() < distance) return true;
  return false;
}

int curvesNear(const core::DegenerateCurves& curves, const core::Vec3& p, double distance) {
  int n = 0;
  for (const core::DegenerateCurve& c : curves.curves()) n += passesNear(c, p, distance);
  return n;
}

TEST(Genus2CleanExample, RemovesTheCurveBesideTheDesignedLineAndKeepsTheRest) {
  const graph::Graph g = graph::loadGraphFile(
      fs::path(TFD_SOURCE_DIR) / "examples" / "genus2_clean.tfd.json", test::builtinNodes());
  test::TempDir dir("genus2-clean");
  graph::CookOptions options;
  options.outDir = dir.path();
  graph::Evaluator ev;
  const graph::CookResult r = ev.cook(g, options);
  ASSERT_EQ(r.report("remove_1")->state, graph::NodeState::Cooked)
      << test::reportText(*r.report("remove_1"));
  ASSERT_TRUE(r.ok());
  const std::string info = test::reportText(*r.report("remove_1"));
  EXPECT_NE(info.find("one-curve removal of the linear curve"), std::string::npos) << info;

  const auto before = r.output<core::DegenerateCurves>("topology", "curves");
  const auto after = r.output<core::DegenerateCurves>("topology_after", "curves");
  ASSERT_EQ(after->size() + 1, before->size()) << before->summary() << "\n" << after->summary();
  const core::Vec3 target(1.7728, -0.4816, 0.0103);
  EXPECT_EQ(curvesNear(*before, target, 0.01), 1);
  EXPECT_EQ(curvesNear(*after, target, 0.1), 0) << "the picked curve is gone";
  // The designed planar wedge loop and linear trisector line.
  EXPECT_EQ(curvesNear(*after, core::Vec3(-1.2, 1.0, 0.0), 0.05), 1);
  EXPECT_EQ(curvesNear(*after, core::Vec3(2.2, 0.0, 0.0), 0.05), 1);
  // Outside the region nothing changed: every remaining curve is one of before's, point for
  // point.
  for (const core::DegenerateCurve& c : after->curves()) {
    bool found = false;
    for (const core::DegenerateCurve& b : before->curves())
      found = found || (b.points.size() == c.points.size() && b.points == c.points);
    EXPECT_TRUE(found) << "curve " << c.id << " through " << c.points.front().transpose();
  }
  EXPECT_TRUE(fs::exists(dir.path() / "genus2_clean_before.vtp"));
  EXPECT_TRUE(fs::exists(dir.path() / "genus2_clean_after.vtp"));
}

}  // namespace
}  // namespace tfd::nodes
