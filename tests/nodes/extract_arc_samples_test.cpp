// ExtractDegenerateCurves.arc_samples only changes how curves are drawn: on the default example
// (boundary-conforming, `boundary_curves: drop`), 0, 2, 4 and 8 samples give the same curves,
// with the same ids, types, ends and skeleton points. Before the boundary filter ignored the
// points inside tets, 8 samples kept 22 curves where 0 kept 12.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/topology/curve_filter.h"
#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

/// The points of a curve on mesh faces, edges and vertices (not the ones inside tets).
std::vector<core::Vec3> skeleton(const core::DegenerateCurve& c) {
  std::vector<core::Vec3> out;
  for (std::size_t i = 0; i < c.points.size(); ++i)
    if (c.sources[i].kind != core::PointSource::Kind::Tet) out.push_back(c.points[i]);
  return out;
}

TEST(ExtractArcSamples, ArcSamplesNeverChangeWhichCurvesExistOrAreDropped) {
  graph::Graph g = graph::loadGraphFile(fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json",
                                        test::builtinNodes());
  g.setParam("ball", "target_tets", std::int64_t(20000));
  graph::CookOptions options;
  options.targets = {"topology"};
  graph::Evaluator ev;

  std::shared_ptr<const core::DegenerateCurves> reference;
  for (int samples : {0, 2, 4, 8}) {
    SCOPED_TRACE("arc_samples " + std::to_string(samples));
    g.setParam("topology", "arc_samples", std::int64_t(samples));
    const graph::CookResult r = ev.cook(g, options);
    ASSERT_TRUE(r.ok());
    auto curves = r.output<core::DegenerateCurves>("topology", "curves");
    ASSERT_TRUE(curves);
    if (!reference) {
      reference = curves;
      EXPECT_GE(reference->size(), 4u) << "the four designed points have curves";
      continue;
    }
    ASSERT_EQ(curves->size(), reference->size());
    for (std::size_t i = 0; i < curves->size(); ++i) {
      const core::DegenerateCurve& a = reference->curves()[i];
      const core::DegenerateCurve& b = curves->curves()[i];
      EXPECT_EQ(b.id, a.id);
      EXPECT_EQ(b.type, a.type);
      EXPECT_EQ(b.closed, a.closed);
      EXPECT_EQ(skeleton(b), skeleton(a)) << "curve " << i;
      EXPECT_NEAR(core::skeletonLength(b), core::skeletonLength(a), 1e-12);
      if (samples > 0 && !a.closed) {
        EXPECT_GT(b.points.size(), a.points.size());
      }
    }
  }
}

}  // namespace
}  // namespace tfd::nodes
