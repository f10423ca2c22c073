// The tets a degenerate curve passes through, found from its points' sources alone: each
// segment lies in its tet (barycentric coordinates of its points are non-negative).
#include "core/topology/curve_tets.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/design/propagate.h"
#include "core/structured_mesh.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {
namespace {

TEST(CurveTets, EverySegmentLiesInItsTet) {
  // A box with a wedge and a trisector point element: curves cross faces, and arc samples add
  // points inside tets.
  const auto mesh = makeBoxMesh(12, 12, 12, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  ConstraintSet set;
  for (const auto& [p, pattern] :
       {std::pair{Vec3(-0.3, 0.05, 0.02), DegeneratePattern::Wedge},
        std::pair{Vec3(0.35, -0.04, 0.1), DegeneratePattern::Trisector}}) {
    PointElement e;
    e.degenerate = true;
    e.field = makeDegenerateLinearization(p, Mat3::Identity(), DegenerateType::Linear, pattern);
    set.points.push_back(e);
  }
  const TensorField field = propagate(mesh, set).field;
  ExtractOptions options;
  options.arcSamples = 3;
  const DegenerateCurves curves = extractDegenerateCurves(field, options);
  ASSERT_GT(curves.size(), 0u);
  std::size_t segments = 0;
  for (const DegenerateCurve& c : curves.curves()) {
    const std::vector<int> tets = segmentTets(*mesh, c);
    const std::size_t n = c.points.size();
    ASSERT_EQ(tets.size(), n < 2 ? 0 : (c.closed && n > 2 ? n : n - 1)) << "curve " << c.id;
    for (std::size_t i = 0; i < tets.size(); ++i, ++segments) {
      ASSERT_GE(tets[i], 0) << "curve " << c.id << " segment " << i;
      const Vec3 a = c.points[i], b = c.points[(i + 1) % n];
      for (const Vec3& p : {a, b, Vec3(0.5 * (a + b))})
        EXPECT_GE(mesh->barycentric(tets[i], p).minCoeff(), -1e-9)
            << "curve " << c.id << " segment " << i;
    }
  }
  EXPECT_GT(segments, 20u);
}

TEST(CurveTets, SourcesMapToTheirTets) {
  const auto mesh = makeBoxMesh(2, 2, 2, Vec3(0, 0, 0), Vec3(1, 1, 1));
  const int face = 0;
  std::vector<int> faceTets;
  for (int t : mesh->faceTets()[face])
    if (t >= 0) faceTets.push_back(t);
  std::sort(faceTets.begin(), faceTets.end());
  EXPECT_EQ(tetsOfSource(*mesh, {PointSource::Kind::Face, face}), faceTets);
  EXPECT_EQ(tetsOfSource(*mesh, {PointSource::Kind::Tet, 5}), std::vector<int>{5});
  const auto around = mesh->vertexTets(13);  // the centre vertex
  EXPECT_EQ(tetsOfSource(*mesh, {PointSource::Kind::Vertex, 13}),
            std::vector<int>(around.begin(), around.end()));
  for (int t : tetsOfSource(*mesh, {PointSource::Kind::Edge, 0})) {
    const auto& tet = mesh->tets()[t];
    const auto& e = mesh->edges()[0];
    EXPECT_NE(std::find(tet.begin(), tet.end(), e[0]), tet.end());
    EXPECT_NE(std::find(tet.begin(), tet.end(), e[1]), tet.end());
  }
}

}  // namespace
}  // namespace tfd::core
